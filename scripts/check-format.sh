#!/usr/bin/env bash
# Checks that every tracked C++ file (*.cpp, *.h) is formatted as .clang-format says, with
# Debian 12's clang-format 14 (scripts/install-deps.sh). Changes nothing: lists the files that
# differ and fails. To fix one: clang-format -i FILE.
#   bash scripts/check-format.sh [FILE...]     default: every tracked .cpp and .h file
set -euo pipefail
arguments=()
for f in "$@"; do
  arguments+=("$(realpath "$f")")  # the files named are relative to where the script was run
done
cd "$(dirname "$0")/.."

clang_format=${CLANG_FORMAT:-}
if [ -z "$clang_format" ]; then
  for candidate in clang-format-14 clang-format; do
    if command -v "$candidate" >/dev/null; then
      clang_format=$candidate
      break
    fi
  done
fi
if [ -z "$clang_format" ]; then
  echo "check-format: clang-format not found (apt-get install clang-format)" >&2
  exit 2
fi

if [ ${#arguments[@]} -gt 0 ]; then
  files=("${arguments[@]}")
else
  mapfile -t files < <(git ls-files -- '*.cpp' '*.h' 2>/dev/null)
  if [ ${#files[@]} -eq 0 ]; then  # not a git checkout (a source archive): the same folders
    mapfile -t files < <(find bench examples include src tests \( -name '*.cpp' -o -name '*.h' \) \
                           -type f 2>/dev/null | sort)
  fi
fi
if [ ${#files[@]} -eq 0 ]; then
  echo "check-format: no C++ files found" >&2
  exit 2
fi

# One clang-format for every file (a process per file is slow on a busy machine); each file that
# differs gets one "FILE:LINE:COL: error: code should be clang-formatted" line.
report=$("$clang_format" --style=file --dry-run --Werror --ferror-limit=1 "${files[@]}" 2>&1) \
  && status=0 || status=$?
mapfile -t differ < <(printf '%s\n' "$report" |
  sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' | sort -u)
if [ $status -ne 0 ] && [ ${#differ[@]} -eq 0 ]; then
  printf '%s\n' "$report" >&2
  echo "check-format: $clang_format failed" >&2
  exit 2
fi

if [ ${#differ[@]} -gt 0 ]; then
  echo "check-format: ${#differ[@]} of ${#files[@]} files differ from .clang-format ($("$clang_format" --version | head -1)):" >&2
  printf '  %s\n' "${differ[@]}" >&2
  exit 1
fi
echo "check-format: ${#files[@]} files formatted"
