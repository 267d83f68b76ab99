#!/usr/bin/env bash
# The test suite: installs what is missing (Debian 12, as root or with sudo), builds Paddy and its
# tests, and runs every test not labelled "long" (the long ones: ctest --test-dir build -L long);
# then the sanitizer runs (scripts/sanitize.sh, docs/reliability.md: AddressSanitizer + UBSan
# over the design-of-experiments and engine suites, the command-line cases and the fuzz replays,
# ThreadSanitizer over the OpenMP force loop). PADDY_SANITIZERS=0 skips those (for a quick local run only).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
ctest --test-dir build -LE long --output-on-failure "$@"
if [ "${PADDY_SANITIZERS:-1}" != "0" ]; then
  ./scripts/sanitize.sh address
  ./scripts/sanitize.sh thread
fi
