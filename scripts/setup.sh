#!/usr/bin/env bash
# Sets candela up on a fresh Debian 12 machine: installs the Debian packages it builds with
# (scripts/install-deps.sh) and builds the `candela` program and the Python module (build/python/)
# in Release into build/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh candela_cli candela_python
