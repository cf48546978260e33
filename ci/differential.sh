#!/usr/bin/env bash
# Run acconform's differential check in CI. Usage: ci/differential.sh [extra acconform check args]
# ACCONFORM_DIR: an acconform checkout to install (non-editable; default .). ACCONFORM_IMPL: the
# command of the port under test (acconform.protocol/1; default: acconform's own port).
# With ACE_ASSEMBLY set: a live campaign on fresh scenes. Without: the recorded corpus replay.
set -euo pipefail
python3 -m pip install --quiet --disable-pip-version-check "${ACCONFORM_DIR:-.}${ACE_ASSEMBLY:+[oracle]}"
failures="${ACCONFORM_FAILURES:-failures}"
args=(--failures "$failures" --no-progress --json "${ACCONFORM_JSON:-acconform.json}" --junit "${ACCONFORM_JUNIT:-acconform.xml}")
if [ -n "${ACCONFORM_IMPL:-}" ]; then args+=(--impl "$ACCONFORM_IMPL"); fi
if [ -n "${ACE_ASSEMBLY:-}" ]; then args+=(--keep-going); fi
exec acconform check "${args[@]}" "$@"
