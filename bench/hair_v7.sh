# One device call: the hair scene after the composite lost its second list walk (the tail from log-transmittance) (25k and 100k
# strands, translucency on, compute hair raster), deep opacity maps beside it.
out=$OUT/r; mkdir -p $out; assets=.device/assets
h="hair --dsm-res 2048 --width 1920 --height 1080"
bin=.device/penumbra; . bench/lib.sh
for n in 25000 100000; do
  run dsm_$n $h --shadow dsm --strands $n
  run dom_$n $h --shadow dom --strands $n
done
for f in $out/*.json; do python3 -c "
import json,sys; d=json.load(open('$f')); print('$f'.split('/')[-1], round(d['frame_ms']['median'],2), ' '.join(f\"{p['name']}={p['median_ms']:.2f}\" for p in d['passes'] if p['median_ms']>0.05))"; done
tar -cf $OUT/r.tar -C $OUT r
