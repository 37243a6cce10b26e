#!/usr/bin/env bash
# Benchmark of --accel bvh against Embree 3 (see BENCHMARKS.md). Installs
# what is missing of the project's packages and of libembree-dev (which
# only the bench needs), fetches Debian's libcgal-demo package and takes
# five meshes from it, generates a 1M-triangle mesh with our own code,
# builds the bench target into build-bench/ and prints the tables.
# Everything fetched or generated goes to bench-data/, which git ignores.
# Usage: scripts/bench.sh [--fast] [--threads N] [--crossover]
set -euo pipefail
cd "$(dirname "$0")/.."
data=bench-data
meshes=(bunny00 fandisk ChineseDragon-10kv armadillo refined_elephant)
seed=../shared/seed/scenes

scripts/setup.sh --packages-only
scripts/install-packages.sh libembree-dev

mkdir -p "$data/cgal"
if [ ! -f "$data/cgal/meshes.done" ]; then
  echo "bench: fetching libcgal-demo"
  (
    cd "$data/cgal"
    apt-get download libcgal-demo
    ar x libcgal-demo_*.deb data.tar.xz
    # The package holds CGAL's own data.tar.gz, which holds data/meshes/.
    tar -xOf data.tar.xz ./usr/share/doc/libcgal-dev/data.tar.gz >cgal-data.tar.gz
    members=()
    for m in "${meshes[@]}"; do members+=("data/meshes/$m.off"); done
    tar -xzf cgal-data.tar.gz --transform='s|.*/||' "${members[@]}"
    rm -f data.tar.xz cgal-data.tar.gz libcgal-demo_*.deb
    touch meshes.done
  )
fi

cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF >/dev/null
cmake --build build-bench --target bench raytrace
bench=build-bench/bin/bench

if [[ " $* " == *" --crossover "* ]]; then
  exec "$bench" --crossover
fi

if [ ! -f "$data/knot1m.off" ]; then
  echo "bench: generating a 1M-triangle torus knot"
  "$bench" --make-knot "$data/knot1m.off" --triangles 1000000
fi
scenes=()
for m in "${meshes[@]}" knot1m; do
  off="$data/cgal/$m.off"
  [ "$m" = knot1m ] && off="$data/knot1m.off"
  [ -f "${off%.off}.sce" ] || "$bench" --make-scene "$off"
  scenes+=("${off%.off}.sce")
done
# Our interiors: long, thin triangles spanning the scene (see scenes/).
scenes+=(scenes/hall/hall.sce scenes/sponge/sponge.sce)
if [ -d "$seed" ]; then
  for s in cube mask rings toon_faces; do scenes=("$seed/$s/$s.sce" "${scenes[@]}"); done
else
  echo "bench: $seed not found, measuring the CGAL and generated meshes only"
fi

echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores"
"$bench" "$@" "${scenes[@]}"
"$bench" --mesh-load "$data/knot1m.off"
