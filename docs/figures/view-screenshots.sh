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
