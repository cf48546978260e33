#!/usr/bin/env bash
# Run acconform's differential check in CI. Usage: ci/differential.sh [extra acconform check args]
# With ACE_ASSEMBLY set: a live campaign on fresh scenes. Without: the recorded corpus replay.
set -euo pipefail
python3 -m pip install --quiet --disable-pip-version-check -e "${ACCONFORM_DIR:-.}${ACE_ASSEMBLY:+[oracle]}"
failures="${ACCONFORM_FAILURES:-failures}"
if [ -n "${ACE_ASSEMBLY:-}" ]; then
  exec acconform check --keep-going --failures "$failures" --no-progress "$@"
else
  exec acconform check --failures "$failures" --no-progress "$@"
fi
