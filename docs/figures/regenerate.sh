#!/bin/sh
# Regenerates the case-study figures of the docs (paper case study 1: H7/js6, H7/g6 and VE1)
# from a Release build. Run from anywhere: sh docs/figures/regenerate.sh
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
fitfeel="$root/build/bin/fitfeel"
figures="$root/docs/figures"
runs=$(mktemp -d)
trap 'rm -rf "$runs"' EXIT
cd "$root"  # the runs' summaries name their scenario files relative to here

# The case-study pictures show the paper's own method (the -paper scenarios) and VE1.
for scenario in h7js6-paper h7g6-paper ve1; do
  "$fitfeel" run "scenarios/paper-case1-$scenario.yaml" --out "$runs/${scenario%-paper}" >/dev/null
done
"$fitfeel" plot trace "$runs/h7js6" "$runs/h7g6" "$runs/ve1" --log -o "$figures/case1-trace.png"
"$fitfeel" plot sms scenarios/paper-case1-h7js6-paper.yaml -o "$figures/case1-sms-h7js6.png"
"$fitfeel" plot sms scenarios/paper-case1-h7g6-paper.yaml -o "$figures/case1-sms-h7g6.png"
"$fitfeel" plot pressure "$runs/h7js6" --depth 20 -o "$figures/case1-pressure-h7js6.png"
# Speed against accuracy over the default grid ladder, 40 seeds per grid (framework/tradeoff):
# x is the tick p99, since the median tick of the table-driven law barely depends on the grid.
"$fitfeel" tradeoff scenarios/paper-case1-h7js6-paper.yaml --seeds 40 --cost p99 \
  -o "$runs/tradeoff-h7js6" 2>/dev/null
cp "$runs/tradeoff-h7js6.png" "$figures/tradeoff-h7js6.png"
cp "$runs/tradeoff-h7js6.csv" "$figures/tradeoff-h7js6.csv"
# The elastic model and the paper's law against CalculiX (tools/fem/data): the FEM agreement
# tests of the 2-D sections and the 3-D bent and lobed shafts write the table, gnuplot draws it.
echo "case,fem_N_per_mm,elastic_N_per_mm,elastic_error,paper_N_per_mm,paper_error" \
  > "$figures/fem-accuracy.csv"
FITFEEL_FEM_ACCURACY_CSV="$figures/fem-accuracy.csv" "$root/build/tests/fitfeel_surface_cylindrical_test" \
  --gtest_filter="ElasticLaw.AgreesWithCalculixOnEveryContactCase:ElasticLaw.AgreesWithCalculixInThreeDimensions" \
  >/dev/null
# The axisymmetric cases (tools/fem/data/axisymmetric.csv): finite hubs, the shaft part way in.
echo "case,fem_N,elastic_N,elastic_error,plane_N,plane_error" > "$figures/fem-axisymmetric.csv"
FITFEEL_FEM_AXISYMMETRIC_CSV="$figures/fem-axisymmetric.csv" \
  "$root/build/tests/fitfeel_surface_cylindrical_test" \
  --gtest_filter="ElasticLaw.AgreesWithCalculixOn*Hub:ElasticLaw.AgreesWithCalculixInTheFirstMillimetre" \
  >/dev/null
(cd "$figures" && gnuplot fem-accuracy.gp)
