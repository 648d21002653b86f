# Error of the normal force against CalculiX, per FEM case, for the paper's per-cell (Winkler)
# law and the elastic model. Data: fem-accuracy.csv (2-D sections, 3-D bent and lobed shafts) and
# fem-axisymmetric.csv (finite hubs), written by the FEM agreement tests (regenerate.sh). Run from
# docs/figures:
# gnuplot fem-accuracy.gp
set terminal pngcairo size 1100,900 font ",10"
set output "fem-accuracy.png"
set datafile separator ","
set datafile columnheaders
set multiplot layout 2,1 title "Total normal force against CalculiX, steel 20 mm in a 30 mm hub (other walls where named)\nBoth laws read the same per-depth tables: equal tick cost (about 0.2 us, cylindrical contact benchmark)"
set ylabel "error against the FEM (%)"
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set boxwidth 0.9
set xtics rotate by -35 noenhanced
set grid ytics
set yrange [-100:*]
set key top right
set title "2-D plane stress sections (lobes, bumps, partial contact) and 3-D bent and lobed shafts, flush in the hub"
plot "fem-accuracy.csv" using ($6*100):xtic(1) title "paper law (per-cell Lame, eqs. 10-11)" lc rgb "#c0504d", \
     "" using ($4*100) title "elastic model (harmonic compliance, non-negative pressure)" lc rgb "#4f81bd"
set title "Axisymmetric finite hubs, 5 um uniform: flush, through, the shaft part way in"
set yrange [-80:30]
set key bottom left
plot "fem-axisymmetric.csv" using ($6*100):xtic(1) title "plane sections (the paper law's per-cell Lame for a uniform interference)" lc rgb "#c0504d", \
     "" using ($4*100) title "elastic model with both parts' axial coupling" lc rgb "#4f81bd"
unset multiplot
