#!/bin/sh
# Runs a tests/interop/ script with Debian's /usr/bin/python3 (the first python3 on PATH may be
# another one without python-can). Without it the test is skipped: exit 77, CTest's
# SKIP_RETURN_CODE for the interop tests.
if [ ! -x /usr/bin/python3 ]; then
  echo "SKIPPED: /usr/bin/python3 not found (Debian: apt-get install python3 python3-can)"
  exit 77
fi
exec /usr/bin/python3 "$@"
