#!/usr/bin/env bash
# Installs missing dependencies (as root), configures and builds into build/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-dependencies.sh
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
if [ ! -f build/CMakeCache.txt ]; then
  cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build build --parallel "$(nproc)"
