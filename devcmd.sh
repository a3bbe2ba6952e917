. .device/env.sh
nvidia-smi --query-gpu=name,temperature.gpu --format=csv,noheader
O=$OUT/s30; mkdir -p $O/suite $O/gather $O/hair
cp -r .device/refs $O/suite/refs
GI=rsm VARIANTS="default: depth350:--rsm-visibility,depth,--rsm-samples,350 views4x350:--rsm-samples,350,--rsm-visibility-points,4" bench/gi_variants.sh .device/penumbra .device/assets $O/suite | tail -30
rm -rf $O/suite/refs
BINS="depth350=.device/penumbra:--rsm-visibility,depth,--rsm-samples,350 default=.device/penumbra views4x350=.device/penumbra:--rsm-samples,350,--rsm-visibility-points,4" bench/rsm_far_ab.sh .device/assets $O/gather | grep -- "-2 " | cut -c1-50
bin=.device/penumbra assets=.device/assets out=$O/hair; . bench/lib.sh
for n in 25000 100000; do run hair-depth350-$n $hair --shadow dsm --strands $n --rsm-visibility depth --rsm-samples 350; run hair-default-$n $hair --shadow dsm --strands $n; done
nvidia-smi --query-gpu=temperature.gpu --format=csv,noheader
tar -czf $OUT/s30.tgz -C $OUT s30 && rm -rf $O
