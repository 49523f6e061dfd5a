#!/usr/bin/env bash
# Runs `vissort collide` with the vissort method and with brute force on every model file below a
# folder (default: Debian's assimp-testmodels, `apt-get install assimp-testmodels`) and compares
# their --pairs-out files: prints SAME, DIFF or the exit codes per file, then a summary. Files
# that do not load must fail both ways with vissort's error line (exit 3), never crash or hang.
#   bash scripts/compare-collisions.sh [FOLDER] [BUILD_DIR]
set -uo pipefail
folder=${1:-/usr/share/assimp/models}
tool=${2:-build}/vissort
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
same=0 diff=0 failed=0 pairs=0 colliding=0
while IFS= read -r -d '' file; do
    timeout 300 "$tool" collide "$file" --threads 1 --pairs-out "$work/v.txt" >/dev/null 2>"$work/v.err"
    a=$?
    timeout 300 "$tool" collide "$file" --method brute --pairs-out "$work/b.txt" >/dev/null 2>"$work/b.err"
    b=$?
    if [ "$a$b" = "00" ]; then
        n=$(wc -l <"$work/b.txt")
        if cmp -s "$work/v.txt" "$work/b.txt"; then
            echo "SAME $n $file"; same=$((same + 1)); pairs=$((pairs + n))
            [ "$n" -gt 0 ] && colliding=$((colliding + 1))
        else
            echo "DIFF $file"; diff=$((diff + 1))
        fi
    elif [ "$a" = 3 ] && [ "$b" = 3 ] && grep -q '^vissort: error: ' "$work/v.err"; then
        # (a few files make assimp itself print a line first; that is the loader's, not ours)
        echo "LOAD-ERROR $file: $(grep '^vissort: error: ' "$work/v.err")"
    else
        echo "FAILED (exit $a / $b) $file"; failed=$((failed + 1))
    fi
done < <(find "$folder" -type f ! -iname '*.png' ! -iname '*.jpg' ! -iname '*.jpeg' ! -iname '*.bmp' \
             ! -iname '*.tga' ! -iname '*.dds' ! -iname '*.txt' ! -iname '*.md' ! -iname '*.mtl' \
             ! -iname '*.bin' -print0 | sort -z)
echo "same: $same ($colliding with collisions, $pairs pairs), different: $diff, crashed or hung: $failed"
[ "$diff" = 0 ] && [ "$failed" = 0 ]
