# One device call: deep shadow maps and deep opacity maps on the hair scene (25k and 100k strands,
# translucency on, compute hair raster): the H100 results of hair_v5/, hair_v6/ and hair_v7/ (the tree
# after each step of session 14, README "H100: hair with camera translucency"). With `images`: also
# both techniques' images at 1280x720 (hair_v4/, docs/images/hair-dsm-h100.png and hair-dom-h100.png).
out=$OUT/r; mkdir -p $out; assets=.device/assets
h="hair --dsm-res 2048 --width 1920 --height 1080"
bin=.device/penumbra; . bench/lib.sh
for n in 25000 100000; do
  run dsm_$n $h --shadow dsm --strands $n
  run dom_$n $h --shadow dom --strands $n
done
if [ "${1:-}" = images ]; then
  for t in dsm dom; do
    $bin render hair --shadow $t --dsm-res 2048 --strands 25000 --width 1280 --height 720 -o $out/hair-$t-h100.png \
      > $out/render_$t.txt 2>&1
  done
fi
summarize
tar -cf $OUT/r.tar -C $OUT r
