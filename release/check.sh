#!/usr/bin/env bash
# Release check (docs/release.md): deploys the reactor to a folder repository, then builds and runs the
# consumer project (release/consumer) from a copy outside the source tree, with a fresh local
# repository that resolves org.jecosys only from that folder, and fails when a game depending on
# jecosys-render gets lwjgl-egl or lwjgl-stb.
#   release/check.sh [WORKDIR]      WORKDIR (default: a new temporary folder) receives repo/ (the
#                                   deployed release), m2/ (the check's own local repository),
#                                   consumer/ and the logs; a temporary one is removed on success
# Environment: MVN (maven binary), M2_REPO (the local repository copied for third-party artifacts,
# default ~/.m2/repository; anything missing there comes from Maven Central).
# Nothing is written into your own local repository.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mvn_bin="${MVN:-mvn}"
m2_src="${M2_REPO:-$HOME/.m2/repository}"
if [ $# -ge 1 ]; then
  work="$(mkdir -p "$1" && cd "$1" && pwd)"
  temporary=""
else
  work="$(mktemp -d "${TMPDIR:-/tmp}/jecosys-release.XXXXXX")"
  temporary=1
fi
repo="$work/repo"
m2="$work/m2"
consumer="$work/consumer"
settings="$work/settings.xml"
rm -rf "$repo" "$m2" "$consumer"

# the project's version: the parent pom's first <version> at project level
version=$(sed -n 's:^  <version>\(.*\)</version>$:\1:p' "$root/pom.xml" | head -n1)
[ -n "$version" ] || { echo "check: no version in $root/pom.xml" >&2; exit 1; }
base="${version%-SNAPSHOT}"
echo "check: JEcoSys $version; work folder $work"

fail() {
  echo "check: FAILED: $*" >&2
  echo "check: the work folder is kept: $work" >&2
  exit 1
}

# runs maven with its output in a log; on failure prints the log's end
run_mvn() { # LOG DIR ARGS...
  local log="$1" dir="$2"
  shift 2
  if ! (cd "$dir" && "$mvn_bin" -B "$@") >"$log" 2>&1; then
    tail -n 40 "$log" >&2
    fail "mvn $* (in $dir); log: $log"
  fi
}

# a local repository of the check's own: a copy of yours for third-party artifacts (saves
# downloading them), less org/jecosys; the deploy and the consumer use it, so nothing is written
# into yours
mkdir -p "$m2"
if [ -d "$m2_src" ]; then
  cp -a "$m2_src/." "$m2/"
fi
rm -rf "$m2/org/jecosys"

# 1. deploy: the release command of docs/release.md, without tests and without installing
start=$SECONDS
echo "check: 1/4 deploying to $repo"
run_mvn "$work/deploy.log" "$root" -Dmaven.repo.local="$m2" -DskipTests -Dmaven.install.skip=true deploy \
  -DaltDeploymentRepository="release-check::file://$repo"
echo "check: deployed in $((SECONDS - start)) s"

# the deployed file of a module: the exact name for a release, the timestamped one for a snapshot
deployed() { # MODULE SUFFIX (.pom, .jar, -sources.jar, -javadoc.jar)
  local dir="$repo/org/jecosys/$1/$version" name
  if [ "$base" = "$version" ]; then
    name="$1-$version$2"
  else # NAME-0.2.0-20261128.101010-1.jar
    name=$(ls "$dir" 2>/dev/null | grep -E "^$1-${base//./\\.}-[0-9]{8}\.[0-9]{6}-[0-9]+${2//./\\.}\$" | sort | tail -n1 || true)
  fi
  [ -n "$name" ] && [ -f "$dir/$name" ] || fail "$1: no $1-$version$2 in $dir"
  echo "$dir/$name"
}
deployed jecosys-parent .pom >/dev/null
deployed jecosys-bom .pom >/dev/null
for module in jecosys-core jecosys-render jecosys-gdx jecosys-jme; do
  deployed "$module" .pom >/dev/null
  deployed "$module" .jar >/dev/null
  sources=$(deployed "$module" -sources.jar)
  javadoc=$(deployed "$module" -javadoc.jar)
  jar tf "$sources" | grep -q '^org/jecosys/.*\.java$' || fail "$module: its sources jar holds no source"
  jar tf "$javadoc" | grep -qx 'index.html' || fail "$module: its Javadoc jar has no index.html"
done
for module in jecosys-app jecosys-example-game jecosys-example-gdx jecosys-example-jme; do
  [ ! -e "$repo/org/jecosys/$module" ] || fail "$module was deployed; it is not published"
done
echo "check: the folder holds parent, bom, and core, render, gdx, jme with sources and Javadoc jars; no app, no examples"

# 2. the consumer, outside the source tree, with the check's local repository emptied of org/jecosys
# again (the deploy cached the folder's metadata there) and the folder as a repository
start=$SECONDS
echo "check: 2/4 building the consumer in $consumer"
rm -rf "$m2/org/jecosys"
cp -a "$root/release/consumer" "$consumer"
rm -rf "$consumer"/*/target "$consumer/target"
cat >"$settings" <<EOF
<settings>
  <localRepository>$m2</localRepository>
  <profiles>
    <profile>
      <id>jecosys-release</id>
      <repositories>
        <repository>
          <id>jecosys-release</id>
          <url>file://$repo</url>
          <releases><enabled>true</enabled></releases>
          <snapshots><enabled>true</enabled></snapshots>
        </repository>
      </repositories>
    </profile>
  </profiles>
  <activeProfiles><activeProfile>jecosys-release</activeProfile></activeProfiles>
</settings>
EOF
mvn_consumer=(-s "$settings" -Djecosys.version="$version")
run_mvn "$work/consumer.log" "$consumer" "${mvn_consumer[@]}" package
# every org.jecosys artifact in the fresh local repository came from the folder
for module in jecosys-parent jecosys-bom jecosys-core jecosys-render jecosys-gdx jecosys-jme; do
  marker="$m2/org/jecosys/$module/$version/_remote.repositories"
  [ -f "$marker" ] || fail "$module was not resolved (no $marker)"
  if grep -v '^#' "$marker" | grep -qv '>jecosys-release=$'; then
    fail "$module: resolved from elsewhere than the folder: $(cat "$marker")"
  fi
done
echo "check: the consumer built in $((SECONDS - start)) s; every org.jecosys module came from the folder"

# 3. run the game's main class on its resolved class path
echo "check: 3/4 running the consumer"
run_mvn "$work/classpath.log" "$consumer" "${mvn_consumer[@]}" -q -pl game dependency:build-classpath \
  -Dmdep.outputFile="$work/game.classpath"
java -Djecosys.expectedVersion="$version" -Djecosys.expectedRepository="$m2/" \
  -cp "$consumer/game/target/classes:$(cat "$work/game.classpath")" com.example.consumer.Main \
  || fail "the consumer's Main"

# 4. what a game depending on jecosys-render gets
echo "check: 4/4 dependency trees"
rm -f "$work/tree.txt"
run_mvn "$work/tree.log" "$consumer" "${mvn_consumer[@]}" -q dependency:tree -DoutputFile="$work/tree.txt" -DappendOutput=true
cat "$work/tree.txt"
if grep -E 'org\.lwjgl:lwjgl-(egl|stb):' "$work/tree.txt"; then
  fail "a game gets lwjgl-egl or lwjgl-stb (above)"
fi
echo "check: no lwjgl-egl, no lwjgl-stb"

echo "check: ok: JEcoSys $version deploys, and a consumer builds and runs against the folder alone"
if [ -n "$temporary" ]; then
  rm -rf "$work"
fi
