# Sourced by CLI tests that check a file against the project's JSON schemas with ajv, as
# tests/cli/show_schema.sh runs it (tests/node, installed by `make node-tools`). Needs $root.
schema_ajv="$root/tests/node/node_modules/.bin/ajv"

# conforms SCHEMA FILE [LOG]: ajv's exit status for FILE (an absolute path: ajv runs in tests/node,
# where its plugins are) against schemas/SCHEMA, its output
# into LOG (default: nowhere).
conforms() {
  (cd "$root/tests/node" && "$schema_ajv" validate --spec=draft2020 -c ajv-formats --strict=true \
     -s "$root/schemas/$1" -d "$2" >"${3:-/dev/null}" 2>&1)
}

# check_conforms SCHEMA FILE WHAT: one of the caller's checks (its `check` and `fail`) that FILE
# conforms to schemas/SCHEMA; without ajv installed it fails.
check_conforms() {
  if [ ! -x "$schema_ajv" ]; then
    echo "FAIL: $schema_ajv missing (make node-tools)"; fail=$((fail + 1)); return
  fi
  local log rc
  log=$(mktemp)
  conforms "$1" "$2" "$log"; rc=$?
  check "$3 conforms to $1 (exit $rc: $(tail -2 "$log"))" "[ $rc -eq 0 ]"
  rm -f "$log"
}
