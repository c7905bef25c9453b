# Shared by bench/run.sh, bench/make-references.sh and bench/scaling.sh (sourced, not run): the
# benchmark scene set, run-time assets, and small helpers. Paths are relative to the repository
# root, which the scripts cd into first.

# The fixed benchmark set, in table order. Per scene: the benchmark spp (at the scene file's
# resolution), the relMSE target for "time to target" (about 10x the reference's own relMSE,
# bench/references/*.json), and the reference spp (two halves of spp/2 with different seeds, at
# 1/4 of the resolution). Change a target or reference spp only together with new references.
bench_all_scenes=(cornell-box smallpt dragon displaced-sphere bunny-sky cornell-glass)
declare -A bench_spp=([cornell-box]=64 [smallpt]=8 [dragon]=16 [displaced-sphere]=8 [bunny-sky]=16 [cornell-glass]=64)
declare -A bench_target=([cornell-box]=0.001 [smallpt]=0.15 [dragon]=0.001 [displaced-sphere]=0.002 [bunny-sky]=0.01 [cornell-glass]=0.002)
declare -A ref_spp=([cornell-box]=32768 [smallpt]=2048 [dragon]=4096 [displaced-sphere]=4096 [bunny-sky]=4096 [cornell-glass]=65536)
ref_factor=4
# The generated mesh of the displaced-sphere scene (candela_make_mesh --triangles).
sphere_triangles=10000000

# Inputs from outside the repository: the shared assets (the Stanford dragon may not be copied
# into the repository), overridable with CANDELA_ASSETS.
assets_dir="${CANDELA_ASSETS:-../shared/assets}"
dragon_asset="$assets_dir/meshes/stanford-dragon/dragon_vrip.ply.gz"

# build_dir and work_dir are set by the calling script.

# The value of a numeric field of the flat JSON that `candela render --stats` writes.
field() { grep -o "\"$2\": [-0-9.e+]*" "$1" | head -1 | awk '{print $2}'; }

# The median of the arguments (numbers).
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }

# Seconds since the epoch, with nanoseconds, for wall times.
now() { date +%s.%N; }

# Floating-point arithmetic: calc '1 / 3'.
calc() { awk "BEGIN {print $1}"; }

commit_id() {
  local c
  c=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
  git diff --quiet HEAD 2>/dev/null || c="$c+dirty"
  echo "$c"
}
cpu_model() { grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'; }

# The scene file a benchmark renders. The dragon and the displaced sphere use meshes made at run
# time in the work folder, so their scene files are copied next to the mesh (prepare_scene).
scene_file() {
  case "$1" in
    dragon | displaced-sphere) echo "$work_dir/$1/$1.json" ;;
    *) echo "bench/scenes/$1.json" ;;
  esac
}

# Makes the run-time inputs of scene $1; returns 1 (with a message) when they cannot be made.
prepare_scene() {
  local name="$1" dir="$work_dir/$1"
  case "$name" in
    dragon)
      if [ ! -f "$dragon_asset" ]; then
        echo "bench: $dragon_asset not found (set CANDELA_ASSETS to the shared assets folder); skipping the dragon" >&2
        return 1
      fi
      mkdir -p "$dir"
      if [ ! -s "$dir/dragon_vrip.ply" ] || [ "$dragon_asset" -nt "$dir/dragon_vrip.ply" ]; then
        gzip -dc "$dragon_asset" >"$dir/dragon_vrip.ply.tmp" && mv "$dir/dragon_vrip.ply.tmp" "$dir/dragon_vrip.ply"
      fi
      cp bench/scenes/dragon.json "$dir/dragon.json"
      ;;
    displaced-sphere)
      mkdir -p "$dir"
      make_sphere_mesh "$sphere_triangles" "$dir/displaced-sphere.ply"
      cp bench/scenes/displaced-sphere.json "$dir/displaced-sphere.json"
      ;;
  esac
}

# Writes the displaced sphere of >= $1 triangles to $2, unless the same request made it already
# (a stamp file beside it records the request; a rebuilt generator makes it again).
make_sphere_mesh() {
  local tool="$build_dir/candela_make_mesh"
  if [ ! -s "$2" ] || [ "$tool" -nt "$2" ] || [ "$(cat "$2.stamp" 2>/dev/null)" != "$1" ]; then
    "$tool" --triangles "$1" "$2.tmp" >/dev/null && mv "$2.tmp" "$2" && echo "$1" >"$2.stamp"
  fi
}

# The reference image of scene $1 (may not exist), and its record (make-references.sh).
reference_file() { echo "bench/references/$1.exr"; }
reference_record() { echo "bench/references/$1.json"; }

# The resolution the scene file asks for, as "W H".
scene_resolution() { grep -o '"resolution": *\[ *[0-9]* *, *[0-9]* *\]' "$1" | grep -o '[0-9][0-9]*' | xargs; }

# The scene file's hash, to tell whether a reference still matches its scene.
scene_hash() { sha256sum "bench/scenes/$1.json" | cut -c1-16; }
