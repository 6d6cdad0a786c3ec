#!/usr/bin/env bash
# Issue 17 item 11 (Robustness.Item11_*): the CLI's numbers are decimal, an underflowing number is
# an error, an empty option value is an error, a failed write is an error, and a missing plot
# interpreter is reported on one line; plus the item 1 and 6 reproducers through `disklab map`.
# Usage: bash robustness_contract.sh <path-to-disklab>
set -u
DISKLAB=${1:?usage: robustness_contract.sh <path-to-disklab>}
source "$(dirname "${BASH_SOURCE[0]}")/contract_lib.bash"

# Item11_NumbersAreDecimal: hexadecimal, inf and nan are not numbers (strtod and CLI11 took them).
expect_usage_error map --strategy polar --uv 0x1p-1,0.5
expect_usage_error map --map radial --center 0,0,1 --normal 0,0,-1 --radius 0x10 --point 0,0,0 --uv 0.3,0.7
expect_usage_error points --strategy polar --count 0x10
expect_usage_error points --strategy polar --count 0b10
expect_usage_error map --strategy polar --uv inf,0.5
expect_usage_error map --strategy polar --uv nan,0.5
# Decimal forms that are numbers still are: sign, no leading digit, exponent, subnormal.
run map --strategy polar --uv +.25,0e0
[[ $RC -eq 0 ]] || fail "'+.25,0e0' rejected: $ERR"
run map --map radial --center 0,0,1 --normal 0,0,-1 --radius 1 --point 1e-310,0,0 --uv 0.3,0.7
[[ $RC -eq 0 ]] || fail "a subnormal coordinate rejected: $ERR"

# Item11_UnderflowIsAnError: 1e-400 is not 0.
expect_usage_error map --strategy polar --uv 1e-400,0.5
expect_usage_error map --map radial --center 0,0,1 --normal 0,0,-1 --radius 1e-400 --point 0,0,0 --uv 0.3,0.7
run map --strategy polar --uv 0e-400,0.5
[[ $RC -eq 0 ]] || fail "an exact zero with a large exponent rejected: $ERR"

# Item11_EmptyValuesAreErrors: --out '' used to mean stdout, --sequences '' every sequence.
expect_usage_error points --strategy polar --count 4 --out ''
expect_usage_error sequences --count 4 --sequences ''
expect_usage_error map --strategy ''

# Item11_FailedWriteIsAnError: stdout on a full device.
if [[ -w /dev/full ]]; then
  "$DISKLAB" map --strategy polar --uv 0.25,0 >/dev/full 2>"$TMP/err"
  rc=$?
  [[ $rc -eq 1 ]] || fail "map > /dev/full: exit $rc, expected 1"
  [[ $(wc -l <"$TMP/err") -eq 1 && $(cat "$TMP/err") == "disklab: error: "* ]] ||
    fail "map > /dev/full: stderr not one error line: $(cat "$TMP/err")"
fi

# Item11_MissingPlotInterpreterIsOneLine.
DISKLAB_PYTHON=/nonexistent/python3 "$DISKLAB" points --strategy polar --count 16 --format png \
  --out "$TMP/p.png" >"$TMP/out" 2>"$TMP/err"
rc=$?
[[ $rc -ne 0 ]] || fail "missing interpreter: exit 0"
[[ $(wc -l <"$TMP/err") -eq 1 ]] || fail "missing interpreter: $(wc -l <"$TMP/err") stderr lines: $(cat "$TMP/err")"
[[ ! -e $TMP/p.png ]] || fail "missing interpreter: left a file behind"

# Item01 and Item06 reproducers: a solid angle whose density overflows is a disk the point cannot
# sample (one error line, exit 2), never pdf inf; a huge disk samples with a finite pdf.
expect_usage_error map --map radial --center 0,0,0 --normal 0,0,1 --radius 1 --point 1e150,0,1e141 --uv 0.3,0.7
run map --map area --center 0,0,1 --normal 0,0,-1 --radius 1e200 --point 0,0,0 --uv 0.3,0.7
[[ $RC -eq 0 && $OUT != *inf* && $OUT != *nan* ]] || fail "item 6 reproducer: exit $RC, output '$OUT' $ERR"

[[ $failures -eq 0 ]] || { echo "$failures failure(s)" >&2; exit 1; }
echo "robustness contract: ok"
