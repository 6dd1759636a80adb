#!/usr/bin/env bash
# Every C++ file of the project's source rooms is as clang-format (Debian 12's, with the project's
# .clang-format) writes it. Fails naming the files that differ and how to mend them.
# Usage: format_check.sh SOURCE_DIR
set -euo pipefail
src="$1"
command -v clang-format > /dev/null || { echo "clang-format not installed"; exit 1; }
cd "$src"
mapfile -t files < <(find app engine widgets tests -name '*.cpp' -o -name '*.h' | sort)
((${#files[@]} > 100)) || { echo "only ${#files[@]} C++ files found under $src"; exit 1; }
differ=()
for f in "${files[@]}"; do
  if ! clang-format --dry-run --Werror "$f" > /dev/null 2>&1; then
    differ+=("$f")
  fi
done
if ((${#differ[@]})); then
  echo "${#differ[@]} of ${#files[@]} files differ from clang-format's layout:"
  printf '  %s\n' "${differ[@]}"
  echo "Mend them with: clang-format -i ${differ[*]}"
  exit 1
fi
echo "all ${#files[@]} C++ files as clang-format writes them"
