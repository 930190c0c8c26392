#!/bin/sh
# Installs gesmi's build and test dependencies from Debian 12 packages.
# Idempotent: packages already present are left alone; runs apt only when something is missing.
set -eu
packages="build-essential cmake pkg-config ccache
 libeigen3-dev libboost-dev libboost-program-options-dev
 libhdf5-dev hdf5-tools libssl-dev libxxhash-dev libgeographiclib-dev libyaml-cpp-dev libhowardhinnant-date-dev libcairo2-dev libpng-dev
 libpixman-1-dev libfontconfig-dev libfreetype-dev libexpat1-dev libbrotli-dev libbz2-dev libaec-dev zlib1g-dev
 libgtest-dev libgmock-dev libbenchmark-dev libmpfi-dev libmpfr-dev libgmp-dev
 python3 python3-dev pybind11-dev python3-numpy python3-h5py python3-matplotlib python3-pytest python3-nmea2 python3-xxhash nlohmann-json3-dev gdal-bin python3-jsonschema
 help2man parallel time"
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
