#!/bin/sh
# Runs a test of the sanitizer build (ctest's CROSSCOMPILING_EMULATOR there): "$@" is the
# test executable and its arguments. LeakSanitizer's stop-the-world tracer sometimes dies
# at a process's exit before it reports anything (google/sanitizers#1353: "Tracer caught
# signal 11", "LeakSanitizer has encountered a fatal error"), in a test or in a binary a
# test runs; that is no outcome of the test. A failed run whose output carries both lines
# and no sanitizer report is run once more; every other outcome stands as it is.
out=$(mktemp) || exit 1
trap 'rm -f "$out"' EXIT
"$@" >"$out" 2>&1
status=$?
cat "$out"
if [ "$status" -ne 0 ] && grep -q "Tracer caught signal" "$out" &&
  grep -q "LeakSanitizer has encountered a fatal error" "$out" &&
  ! grep -qE "ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:" "$out"; then
  echo "lsan_tracer_retry: LeakSanitizer's tracer died at an exit (google/sanitizers#1353); running the test once more"
  "$@"
  exit $?
fi
exit "$status"
