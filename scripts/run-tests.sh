#!/usr/bin/env bash
# Builds pilempm and runs the test suite: unit, verification and validation tests.
# Full-size runs carry the label `long` and are left out; run them with
#   ctest --test-dir build -L long
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
ctest --test-dir build -LE long --output-on-failure --parallel "$(nproc)"
