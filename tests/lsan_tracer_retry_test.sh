#!/bin/sh
# tests/lsan_tracer_retry.sh reruns a run once only where LeakSanitizer's tracer died and
# nothing else failed: a fake test that fails with the tracer's lines on its first run
# passes on its second; one that reports a leak, one whose tracer dies twice and one that
# fails plainly keep their failure and run once (counted in a file).
set -u
retry="$(dirname "$0")/lsan_tracer_retry.sh"
dir=$(mktemp -d) || exit 1
trap 'rm -rf "$dir"' EXIT
tracer='echo "Tracer caught signal 11: addr=0x0"; echo "==1==LeakSanitizer has encountered a fatal error."'
fails=0
# expect NAME WANTED_STATUS WANTED_RUNS SCRIPT: SCRIPT sees the run number in $n.
expect() {
  rm -f "$dir/runs"
  printf '%s\n' "n=\$(( \$(cat '$dir/runs' 2>/dev/null || echo 0) + 1 )); echo \$n > '$dir/runs'; $4" > "$dir/fake.sh"
  "$retry" sh "$dir/fake.sh" > "$dir/out" 2>&1
  status=$?
  runs=$(cat "$dir/runs")
  if [ "$status" -ne "$2" ] || [ "$runs" -ne "$3" ]; then
    echo "FAIL $1: status $status after $runs run(s), wanted $2 after $3"
    cat "$dir/out"
    fails=$((fails + 1))
  else
    echo "ok $1"
  fi
}
expect "passes at once" 0 1 'exit 0'
expect "tracer died once" 0 2 "if [ \$n -eq 1 ]; then $tracer; exit 1; fi; exit 0"
expect "tracer died twice" 1 2 "$tracer; exit 1"
expect "a leak" 1 1 "echo 'ERROR: LeakSanitizer: detected memory leaks'; $tracer; exit 1"
expect "undefined behaviour" 1 1 "echo 'x.cpp:1:2: runtime error: signed integer overflow'; $tracer; exit 1"
expect "a plain failure" 3 1 'echo "[  FAILED  ] A.B"; exit 3'
expect "half the signature" 1 1 'echo "Tracer caught signal 11"; exit 1'
[ "$fails" -eq 0 ]
