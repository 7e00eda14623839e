# Sourced by the CLI tests that count named checks: `check NAME STATUS` counts a pass, or prints
# "FAIL: NAME" and counts a failure; the test ends with its counts. Take the status into a
# variable before the call when the name holds a $(...), which would set $? to its own status.
fail=0
passed=0
check() {  # check NAME CONDITION-EXIT-STATUS
  if [ "$2" -eq 0 ]; then passed=$((passed + 1)); else echo "FAIL: $1"; fail=$((fail + 1)); fi
}
