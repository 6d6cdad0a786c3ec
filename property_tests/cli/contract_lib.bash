# Shared by the CLI contract scripts (property_tests/cli/*.sh); sourced, never run as a test
# (ctest registers *.sh only). Provides a temporary folder, failure counting and the checks
# every subcommand's contract repeats.
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
failures=0

fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

run() {  # run ARGS... -> sets OUT, ERR, RC ($TMP/out, $TMP/err hold the raw streams)
  "$DISKLAB" "$@" >"$TMP/out" 2>"$TMP/err"
  RC=$?
  OUT=$(cat "$TMP/out")
  ERR=$(cat "$TMP/err")
}

expect_usage_error() {  # ARGS...: exit 2, exactly one stderr line "disklab: error: ...", no stdout
  run "$@"
  local lines
  lines=$(wc -l <"$TMP/err")
  if [[ $RC -ne 2 ]]; then fail "'$*': exit $RC, expected 2 (stderr: $ERR)"; return; fi
  if [[ $lines -ne 1 || $ERR != "disklab: error: "* ]]; then fail "'$*': stderr not one error line: $ERR"; fi
  if [[ -s $TMP/out ]]; then fail "'$*': printed to stdout on error: $OUT"; fi
}

# relclose A B TOL: |A - B| <= TOL * max(1, |B|)
relclose() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; s = (b < 0 ? -b : b); if (s < 1) s = 1; exit !(d <= t * s) }'; }
