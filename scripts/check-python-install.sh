#!/usr/bin/env bash
# Checks the Python module as a user installs it (docs/python.md): a virtual environment made
# with --system-site-packages (Debian's Python is externally managed), `pip install
# --no-build-isolation --no-index .` (Debian's packages only: nothing may be downloaded), then,
# from outside the repository, the installed module imported and its array and lifetime tests
# run against it.
#   bash scripts/check-python-install.sh
# VISSORT_CHECK_BUILD_DIR=DIR builds the module in DIR (an existing build tree to reuse);
# otherwise setup.py's default, build-python/.
set -euo pipefail
cd "$(dirname "$0")/.."
source_dir=$PWD
work=$(mktemp -d "${TMPDIR:-/tmp}/vissort-check-python.XXXXXX")
trap 'rm -rf "$work"' EXIT

bash scripts/install-deps.sh
/usr/bin/python3 -m venv --system-site-packages "$work/venv"
if [ -n "${VISSORT_CHECK_BUILD_DIR:-}" ]; then
  export VISSORT_CMAKE_BUILD_DIR
  VISSORT_CMAKE_BUILD_DIR=$(realpath -m "$VISSORT_CHECK_BUILD_DIR")
fi
"$work/venv/bin/pip" install --no-build-isolation --no-index --quiet "$source_dir"

cd "$work"
installed=$("$work/venv/bin/python" -c 'import vissort, os; print(os.path.dirname(vissort.__file__))')
case "$installed" in
  "$work/venv/"*) ;;
  *) echo "check-python-install: vissort imported from $installed, not the environment" >&2
     exit 1 ;;
esac
for f in __init__.py __init__.pyi py.typed batch/__init__.py batch/__main__.py; do
  [ -e "$installed/$f" ] || { echo "check-python-install: $f was not installed" >&2; exit 1; }
done
"$work/venv/bin/python" -m pytest -q -p no:cacheprovider --rootdir "$work" \
  "$source_dir/python/tests/test_arrays.py" "$source_dir/python/tests/test_lifetimes.py"
# The batch command as installed, on two local Dask workers (python3-distributed).
"$work/venv/bin/python" -m vissort.batch collide builtin:bunnies --frames 4 --chunk-frames 2 \
  --local-workers 2 -q -o "$work/pairs.npz"
[ -s "$work/pairs.npz" ] || { echo "check-python-install: the batch wrote no pairs" >&2; exit 1; }
echo "check-python-install: vissort $("$work/venv/bin/python" -c 'import vissort; print(vissort.__version__)') installed in a virtual environment and tested"
