#!/usr/bin/env bash
# The main job: installs what is missing (Debian 12, as root or with sudo), builds Paddy, and runs
# the default experiment. Arguments are passed to `paddy run` (e.g. --set n=5000 --threads 2).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
exec build/bin/paddy run experiments/column_collapse.lua --out results/column_collapse "$@"
