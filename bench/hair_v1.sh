# One device call: hair at 25k/100k strands, two binaries (penumbra-base: main at 2acae8f; penumbra: the
# same with one atomic per subgroup for list nodes, an experiment that measured no gain and was dropped).
out=$OUT/r; mkdir -p $out; assets=.device/assets
h="hair --shadow dsm --dsm-res 2048 --width 1920 --height 1080"
for b in penumbra-base penumbra; do
  bin=.device/$b
  . bench/lib.sh
  run ${b}_25k $h --strands 25000
  run ${b}_100k $h --strands 100000
done
bin=.device/penumbra
run new_25k_notr $h --strands 25000 --translucency off
run new_25k_pcf hair --shadow pcf --width 1920 --height 1080 --strands 25000
run new_25k_dt $h --strands 25000 --dsm-depth-test on
summarize
tar -cf $OUT/r.tar -C $OUT r
