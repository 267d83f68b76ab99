#!/usr/bin/env bash
# The test suite: installs what is missing (Debian 12, as root or with sudo), builds Paddy and its
# tests, and runs every test not labelled "long" (the long ones: ctest --test-dir build -L long).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
exec ctest --test-dir build -LE long --output-on-failure "$@"
