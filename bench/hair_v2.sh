# One device call: the hair scene at 25k and 100k strands with the compute hair raster (the
# default on the H100: --raster auto) against main before it (penumbra-base, 2acae8f), and the
# hardware raster on the same binary.
out=$OUT/r; mkdir -p $out; assets=.device/assets
h="hair --shadow dsm --dsm-res 2048 --width 1920 --height 1080"
bin=.device/penumbra-base; . bench/lib.sh
run base_25k $h --strands 25000
bin=.device/penumbra
run new_25k $h --strands 25000
run new_100k $h --strands 100000
run new_25k_hw $h --strands 25000 --raster hardware
run new_25k_notr $h --strands 25000 --translucency off
summarize
grep -h "translucency:\|dsm:" $out/new_25k.txt $out/new_100k.txt | head -4
tar -cf $OUT/r.tar -C $OUT r
