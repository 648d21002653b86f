#!/bin/sh
# Screenshots of `fitfeel view` for the scenarios figures/README.md shows (headless Chromium, each
# at 45 % of its finished virtual run), through the same harness as the browser test. Run from the
# repository root after a Release build: sh docs/figures/view-screenshots.sh
set -e
for name in key-parallel knuckle-bearing paper-case1-h7g6 paper-case1-h7js6 paper-case1-ve1 \
    pin-cylindrical square-shaft taper-pin; do
  bash tests/browser/viewer_browser_test.sh build/bin/fitfeel "scenarios/$name.yaml" \
    "docs/figures/view-$name.png"
done
# The live views, after the browser tests' actions: an edit from js6 to k6 (the js6 pass dashed as
# "before the edit"), and a comparison switched to B and back to A (B's pass dashed).
LIVE_SIZE=1280x1180 bash tests/browser/live_browser_test.sh build/bin/fitfeel \
  docs/figures/view-live-edit.png tests/browser/live_edit_act.js scenarios/fits-20mm-h7js6.yaml --edit
LIVE_SIZE=1280x1000 bash tests/browser/live_browser_test.sh build/bin/fitfeel \
  docs/figures/view-compare.png tests/browser/live_compare_act.js scenarios/paper-case1-h7g6.yaml \
  --compare scenarios/paper-case1-h7js6.yaml
