#!/usr/bin/env bash
# Installs everything vissort needs to build and test on Debian 12, from Debian's packages.
# Idempotent; run as root. Each package and why: docs/development.md, "Dependencies".
set -euo pipefail

packages=(
  ca-certificates
  g++ cmake make             # C++20 compiler and build
  libassimp-dev              # reading OBJ, PLY, STL, glTF/GLB and the rest
  libmeshoptimizer-dev       # levels of detail: simplified meshes (meshopt_simplify)
  zlib1g-dev                 # assimp's CMake package links libz.so but does not depend on it
  libglm-dev                 # camera and transform maths
  nlohmann-json3-dev         # JSON scenes and --json output
  libcli11-dev               # command-line parsing
  libembree-dev              # ray casting for the exact oracle and the ground truth
  libpugixml-dev             # reading VTK XML grids (.vtu)
  libgmp-dev pkgconf         # exact rational arithmetic where float cannot decide (the exact fragment model)
  libegl-dev libopengl-dev   # headless OpenGL: EGL and glvnd's libOpenGL (the gl oracle)
  libgl-dev                  # the OpenGL 4.5 core headers (GL/glcorearb.h)
  libegl-mesa0               # Mesa's EGL: the surfaceless platform, and the device platform
  libgl1-mesa-dri            # llvmpipe: OpenGL on the CPU, where there is no GPU driver
  libstb-dev                 # PNG output of the renderer (stb_image_write)
  libglfw3-dev               # vissort view: the window and its input
  libimgui-dev               # vissort view: the panel (Dear ImGui, with its GLFW and OpenGL 3 backends)
  xvfb xauth                 # tests only: vissort view's tests run in a virtual X server (xvfb-run)
  libgtest-dev               # the test suite
  libbenchmark-dev           # the Google Benchmark suite (built by the test script, not run)
  libbullet-dev              # the bullet collision peer
  libfcl-dev                 # the fcl collision peer
  libcgal-dev                # tests only: exact reference predicates for the collision tests
  clang-format               # scripts/check-format.sh: clang-format 14, as .clang-format expects
  python3-dev pybind11-dev   # the Python module (python/, docs/python.md)
  python3-numpy              # its arrays
  python3-venv python3-setuptools python3-wheel  # pip install . in a virtual environment
                             # (scripts/check-python-install.sh; pip builds a wheel with it)
  python3-distributed        # vissort.batch: batches of frames on a Dask cluster (docs/batch.md)
  python3-pandas             # vissort.batch's per-frame statistics as a DataFrame
  python3-pytest             # tests only: the module's tests (python/tests)
  python3-pil                # tests only: reading the command line's PNGs to compare images
  python3-matplotlib         # tests only: docs/python.md's examples show images with it
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing ${missing[*]}; run this script as root" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends "${missing[@]}"
