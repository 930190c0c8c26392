#!/bin/sh
# Installs gesmi's dependencies from Debian 12 packages:
#   tools/install_deps.sh demo   what building and running the gesmi command needs
#   tools/install_deps.sh        the same, and what the tests, the benchmarks and the
#                                Python module need (also: tools/install_deps.sh test)
# Idempotent: packages already present are left alone; runs apt only when something is missing.
set -eu
build="build-essential cmake ninja-build pkg-config ccache
 libeigen3-dev libboost-dev libboost-program-options-dev
 libhdf5-dev libssl-dev libxxhash-dev libgeographiclib-dev libyaml-cpp-dev libhowardhinnant-date-dev
 libcairo2-dev libpng-dev nlohmann-json3-dev"
# The static archives of GESMI_STATIC_ARCHIVES (tools/static_archives.cmake) and what
# the tests, the benchmarks, the man page and the Python module use.
rest="hdf5-tools libpixman-1-dev libfontconfig-dev libfreetype-dev libexpat1-dev libbrotli-dev libbz2-dev libaec-dev zlib1g-dev
 libgtest-dev libgmock-dev libbenchmark-dev libmpfi-dev libmpfr-dev libgmp-dev coinor-libclp-dev
 python3 python3-dev pybind11-dev python3-numpy python3-h5py python3-matplotlib python3-pytest python3-nmea2 python3-xxhash
 gdal-bin python3-jsonschema help2man parallel time"
case "${1:-test}" in
  demo) packages="$build" ;;
  test) packages="$build $rest" ;;
  *) echo "usage: tools/install_deps.sh [demo|test]" >&2; exit 2 ;;
esac
missing=""
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "installing:$missing" >&2
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing >/dev/null
