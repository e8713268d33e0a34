#!/usr/bin/env bash
# Regenerates the parameter docs from the tables in the code: docs/parameters.md and the
# block between "<!-- parameters -->" and "<!-- /parameters -->" in each docs/methods/ID.md.
# Usage: scripts/update_docs.sh [SSFX]   (default build/release/ssfx)
#        scripts/update_docs.sh --check SSFX OUT_DIR   (writes nothing in docs/; exit 1 on a
#        difference, naming the file: the CLI test)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
check=0
if [ "${1:-}" = "--check" ]; then check=1; shift; fi
ssfx=${1:-$root/build/release/ssfx}
out=${2:-}
[ -x "$ssfx" ] || { echo "update_docs: no ssfx at $ssfx (make build)" >&2; exit 2; }
# FILE with its parameter block replaced by TABLE (ENVIRON keeps the table's backslashes).
fill() {
  T="$2" awk '/^<!-- parameters -->$/ { print; printf "%s", ENVIRON["T"]; skip = 1; next }
              /^<!-- \/parameters -->$/ { skip = 0 } !skip' "$1"
}
status=0
update() {  # update FILE CONTENTx (the x keeps $(...) from eating trailing newlines)
  local content=${2%x}
  if [ "$check" = 1 ]; then
    local got="$out/$(basename "$1")"
    printf '%s' "$content" >"$got"
    cmp -s "$got" "$1" || { echo "update_docs: $1 is not what the tables give (scripts/update_docs.sh)" >&2; status=1; }
  else
    printf '%s' "$content" >"$1.tmp" && mv "$1.tmp" "$1"
  fi
}
[ "$check" = 0 ] || mkdir -p "$out"
update "$root/docs/parameters.md" "$("$ssfx" methods --markdown; printf x)"
for doc in "$root"/docs/methods/*.md; do
  id=$(basename "$doc" .md)
  grep -q '^<!-- parameters -->$' "$doc" || continue
  table=$("$ssfx" methods --markdown --method "$id"; printf x)
  update "$doc" "$(fill "$doc" "${table%x}"; printf x)"
done
exit $status
