#!/bin/sh
# SPDX-License-Identifier: MIT
# pkg_config_consumer.sh CXX SOURCE OUT: compile SOURCE against roiclip-core as pkg-config
# describes it (PKG_CONFIG_PATH names the installed prefix's lib/pkgconfig), then run it.
set -eu
cxx=$1
source=$2
out=$3
pkg-config --print-errors --exists roiclip-core
# shellcheck disable=SC2046  # pkg-config's flags are meant to be split
"$cxx" -std=c++17 "$source" -o "$out" $(pkg-config --cflags --libs roiclip-core)
"$out"
