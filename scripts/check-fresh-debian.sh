#!/usr/bin/env bash
# Checks the README's two commands and docs/python.md's pip install the way a newcomer meets
# them: a minimal Debian 12 (debootstrap --variant=minbase bookworm: no compiler, no cmake, no
# git), a clean clone of this repository's HEAD inside, both commands run as root in a chroot
# (with /dev, /proc and /sys mounted and /etc/resolv.conf copied in), then the module installed
# with pip in a virtual environment and imported. Run it before calling a change to packaging or
# dependencies done. Needs root and Debian's mirror; took 13 minutes on the 2-core VM.
# Then docs/batch.md's command on two local Dask workers, with the installed module.
#   bash scripts/check-fresh-debian.sh [DIR]     DIR: the new root (default /var/tmp/vissort-fresh,
#                                                removed first)
#   VISSORT_FRESH_SKIP_TESTS=1                   the demo and the pip install only
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$PWD
root=${1:-/var/tmp/vissort-fresh}
mirror=${VISSORT_FRESH_MIRROR:-http://deb.debian.org/debian}

say() { echo "check-fresh-debian: $*"; }
fail() {
  echo "check-fresh-debian: $*" >&2
  exit 1
}
[ "$(id -u)" = 0 ] || fail "run as root (debootstrap and chroot need it)"

if ! command -v debootstrap >/dev/null || ! command -v git >/dev/null; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap git >/dev/null
fi

mounted=()
unmount_all() {
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    umount -l "${mounted[i]}" 2>/dev/null || true
  done
}
trap unmount_all EXIT

for m in dev/pts dev proc sys; do
  if mountpoint -q "$root/$m" 2>/dev/null; then umount -l "$root/$m"; fi
done
rm -rf "$root"
say "debootstrap --variant=minbase bookworm $root"
debootstrap --variant=minbase bookworm "$root" "$mirror" >"$root.debootstrap.log" 2>&1 ||
  fail "debootstrap failed: see $root.debootstrap.log"

# A clean clone of what is committed: nothing ignored or untracked travels.
git clone --quiet --no-local "$repo" "$root/root/vissort"
for m in dev dev/pts proc sys; do
  mount --bind "/$m" "$root/$m"
  mounted+=("$root/$m")
done
cp /etc/resolv.conf "$root/etc/resolv.conf"

in_root() { chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin \
  LANG=C.UTF-8 /bin/bash -c "cd /root/vissort && $1"; }

for tool in g++ cmake git; do
  if in_root "command -v $tool >/dev/null"; then fail "the new root already has $tool: not fresh"; fi
done

say "README, first command: bash scripts/demo.sh"
in_root "bash scripts/demo.sh" || fail "bash scripts/demo.sh failed in the fresh root"
in_root "test -s out/bunnies-transparent.png" || fail "the demo wrote no out/bunnies-transparent.png"

if [ -z "${VISSORT_FRESH_SKIP_TESTS:-}" ]; then
  say "README, second command: bash scripts/test.sh"
  in_root "bash scripts/test.sh" || fail "bash scripts/test.sh failed in the fresh root"
fi

# docs/python.md's install, word for word, from the repository root.
say "docs/python.md: pip install in a virtual environment"
in_root "python3 -m venv --system-site-packages .venv &&
  .venv/bin/pip install --no-build-isolation . &&
  cd / && /root/vissort/.venv/bin/python -c 'import vissort; print(vissort.__version__)'" ||
  fail "docs/python.md's pip install failed in the fresh root"
# docs/batch.md's command, on two local Dask workers (python3-distributed, from install-deps.sh).
say "docs/batch.md: python3 -m vissort.batch on two local workers"
in_root "cd / && /root/vissort/.venv/bin/python -m vissort.batch collide builtin:bunnies \
  --frames 4 --chunk-frames 2 --local-workers 2 -q -o /tmp/pairs.npz && test -s /tmp/pairs.npz" ||
  fail "python3 -m vissort.batch failed in the fresh root"
if [ -z "${VISSORT_FRESH_SKIP_TESTS:-}" ]; then
  say "both README commands and the pip install passed on a fresh Debian 12 ($root)"
else
  say "the README's first command and the pip install passed on a fresh Debian 12 ($root; tests skipped)"
fi
