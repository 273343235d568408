#!/usr/bin/env bash
# Builds pilempm and runs the default case: the drivability study of the North Sea
# monopile of seed 001 (SRD, blow count and driving stresses against depth).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
build/pilempm run cases/drivability/north-sea-monopile.yaml --out results/north-sea-monopile-drivability "$@"
