#!/usr/bin/env bash
# The main job: installs what is missing (Debian 12, as root or with sudo), builds Paddy, and runs
# the default experiment. Arguments are passed to `paddy run` (e.g. --set particle_diameter=0.01 --threads 2).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
exec build/bin/paddy run experiments/slump.lua --out results/slump "$@"
