#!/usr/bin/env bash
# Builds pilempm and runs the default case: one blow on the North Sea monopile of seed 001.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
build/pilempm run cases/pile-wave/north-sea-monopile.yaml --out results/north-sea-monopile "$@"
