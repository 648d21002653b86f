#!/bin/sh
# Screenshots of `fitfeel view` for every shipped scenario (headless Chromium, each at 45 % of its
# finished virtual run), through the same harness as the browser test. Run from the repository
# root after a Release build: sh docs/figures/view-screenshots.sh
set -e
for s in scenarios/*.yaml; do
  name=$(basename "$s" .yaml)
  bash tests/browser/viewer_browser_test.sh build/bin/fitfeel "$s" "docs/figures/view-$name.png"
done
