#!/usr/bin/env bash
# The code's formatting (.clang-format, pinned to clang-format 14): every C++ source and
# header of the project is as clang-format-14 leaves it. Usage: check_format.sh SOURCE_DIR
# Exit 77 (skipped) when clang-format-14 is not installed (scripts/setup.sh installs it).
set -u
src=$1
fmt=$(command -v clang-format-14) || { echo "format: clang-format-14 not installed; skipped"; exit 77; }
cd "$src" || exit 1
files=$(find src include apps tests bench fuzz python -name node_modules -prune -o \
          \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -print | sort)
[ "$(wc -w <<<"$files")" -gt 150 ] || { echo "format: only $(wc -w <<<"$files") files under $src: wrong directory?"; exit 1; }
bad=$("$fmt" --dry-run --Werror $files 2>&1 | grep -oE '^[^:]+:[0-9]+:[0-9]+: error' | cut -d: -f1 | sort -u)
if [ -n "$bad" ]; then
  echo "format: not as clang-format-14 leaves them (make format):"
  echo "$bad" | sed 's/^/  /'
  exit 1
fi
echo "format: $(wc -w <<<"$files") files formatted"
