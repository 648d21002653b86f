# Draws a stability map written by `fitfeel stability` (framework/stability/README.md):
# stiffness at the device (x) against rate (y), direct rendering stable / unstable and coupled
# rendering stable, for one virtual damping B, with the passivity bound b = K T / 2 + |B|.
#   gnuplot -e "map='map.csv'; out='map.png'; b=5; B=0" framework/stability/stability_map.gp
# map: the CSV; out: a PNG to write; b: the device's damping (N*s/m); B: which damping column.
if (!exists("b")) b = 5.0
if (!exists("B")) B = 0.0
set datafile separator ','
set terminal pngcairo size 900,600
set output out
set logscale xy
set xlabel 'contact stiffness at the device K (N/m)'
set ylabel 'rate 1/T (Hz)'
set title sprintf('virtual damping B = %g N*s/m, device damping b = %g N*s/m', B, b)
set key top left opaque box
set yrange [100:10000]
set parametric
set trange [100:10000]
same(x) = abs(x - B) < 1e-9
plot map using ((strcol(1) eq 'direct' && same($4) && $6 == 1) ? $3 : 1/0):2 \
         with points pt 7 lc rgb 'forest-green' title 'direct, stable', \
     map using ((strcol(1) eq 'direct' && same($4) && $6 == 0) ? $3 : 1/0):2 \
         with points pt 6 lc rgb 'red' title 'direct, unstable', \
     map using ((strcol(1) eq 'coupled' && same($4) && $6 == 1) ? $3 : 1/0):($2 * 1.08) \
         with points pt 5 ps 0.6 lc rgb 'blue' title 'coupled, stable (drawn just above)', \
     map using ((strcol(1) eq 'coupled' && same($4) && $6 == 0) ? $3 : 1/0):($2 * 1.08) \
         with points pt 4 lc rgb 'purple' title 'coupled, unstable', \
     2 * (b - abs(B)) * t, t with lines lc rgb 'black' title 'b = K T / 2 + |B|'
