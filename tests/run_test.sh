#!/bin/sh
# Runs a test that needs something a machine may lack (python3 and python-can, the python canopen
# peer or the corpus in ../shared, vcan), and says what happens when it is missing:
#   run_test.sh KIND python3 SCRIPT ARGS...   SCRIPT with Debian's /usr/bin/python3 (the first
#                                            python3 on PATH may be another one, without python-can)
#   run_test.sh KIND skip MESSAGE             nothing to run here: skip with MESSAGE
#   run_test.sh KIND COMMAND ARGS...          COMMAND; its exit status 77 means "skipped"
# A skip exits 77 (CTest's SKIP_RETURN_CODE of these tests) after a "SKIPPED (KIND): why" line
# (tests/skip_report.py lists them after a run). Under CI=true it exits 1 instead, after the same
# line: CI must not pass by skipping. KIND (python, corpus, vcan, ...) may skip under CI only
# when $FIELDCODEC_CI_MAY_SKIP lists it (.ci/run keeps that list and the reasons). The same rule
# for doctest cases: tests/skip.hpp.
kind="$1"
shift

# $1: why (printed as "SKIPPED (KIND): why")
skipped() {
  echo "SKIPPED ($kind): $1"
  if [ "${CI:-}" = "true" ]; then
    case " $(echo "${FIELDCODEC_CI_MAY_SKIP:-}" | tr ',' ' ') " in
      *" $kind "*) exit 77 ;;
    esac
    echo "FAILED: CI=true, and a test that needs '$kind' may not skip there (the lines above say" \
      "what is missing; .ci/deps installs it, FIELDCODEC_CI_MAY_SKIP lists what may skip)"
    exit 1
  fi
  exit 77
}

case "$1" in
  skip)
    shift
    skipped "$*"
    ;;
  python3)
    shift
    if [ ! -x /usr/bin/python3 ]; then
      skipped "/usr/bin/python3 not found (Debian: apt-get install python3 python3-can)"
    fi
    set -- /usr/bin/python3 "$@"
    ;;
esac
"$@"
status=$?
if [ "$status" -eq 77 ]; then skipped "exit status 77, the lines above say why"; fi
exit "$status"
