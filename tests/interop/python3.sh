#!/bin/sh
# Runs a tests/interop/ script with Debian's /usr/bin/python3 (the first python3 on PATH may be
# another one without python-can). Without it the test is skipped: exit 77, CTest's
# SKIP_RETURN_CODE for the interop tests; under CI=true a missing python3 fails instead.
if [ ! -x /usr/bin/python3 ]; then
  if [ "${CI:-}" = true ]; then
    echo "FAILED: /usr/bin/python3 not found, and under CI=true the test must run (.ci/deps base)"
    exit 1
  fi
  echo "SKIPPED: /usr/bin/python3 not found (Debian: apt-get install python3 python3-can)"
  exit 77
fi
exec /usr/bin/python3 "$@"
