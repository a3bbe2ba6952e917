# One device call: where the hair frame's time goes after the compute hair raster (25k strands):
# the DSM filter width and list cap (both read by the composite's lookups and by dsm.resolve), GI
# off, hard opaque shadows, and a point light's cube of six DSM faces.
out=$OUT/r; mkdir -p $out; assets=.device/assets
h="hair --shadow dsm --dsm-res 2048 --width 1920 --height 1080 --strands 25000"
bin=.device/penumbra; . bench/lib.sh
run base $h
run filter0 $h --dsm-filter 0
run maxlist16 $h --dsm-max-list 16
run gi_none $h --gi none
run notr $h --translucency off
run point $h --light point,0.6,1.2,-0.4,3
summarize
tar -cf $OUT/r.tar -C $OUT r
