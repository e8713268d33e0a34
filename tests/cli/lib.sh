# Shared by the CLI test scripts (sourced): `check NAME EXPECTED_EXIT CMD...` runs CMD with
# its stdout and stderr in $OUT/NAME.out and $OUT/NAME.err, and sets fail=1 (printing the
# stderr) when its exit status is not the expected one.
check() {
  local name=$1 want=$2; shift 2
  "$@" >"$OUT/$name.out" 2>"$OUT/$name.err"
  local got=$?
  if [ "$got" != "$want" ]; then echo "FAIL $name: exit $got, expected $want"; cat "$OUT/$name.err"; fail=1; fi
}
