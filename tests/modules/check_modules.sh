#!/usr/bin/env bash
# The module rules (docs/architecture.md), checked on the sources and on the build's link
# lines. Usage: check_modules.sh SOURCE_DIR LINKS_FILE
#   includes: each module's folders (src/M, include/ssfx/M) include ssfx headers of the
#             modules below it only, and none of the third-party libraries it must not link;
#   links:    each library target's link libraries (LINKS_FILE, written by CMake) name none
#             of the libraries it must not link.
set -u
src=$1
links=$2
fail=0
bad() { echo "module rule: $*" >&2; fail=1; }

# module -> the ssfx modules it may include (itself included)
declare -A allowed=(
  [core]="core"
  [io]="core io"
  [aa]="core aa"
  [ao]="core io ao"
  [scene]="core io ao scene"
  [vk]="core vk"
  [render]="core io ao scene vk render"
  [deferred]="core io ao scene deferred"
  [gpu]="core aa ao vk gpu"
  [gpu_deferred]="core io aa ao scene vk render deferred gpu"
  [eval]="core io aa ao scene vk render gpu deferred eval"
)
# module -> third-party headers it must not include (a regex on the include)
declare -A forbidden=(
  [core]="cairo|vulkan|assimp|embree|glm/|stb/"
  [io]="cairo|vulkan|assimp|embree|glm/|stb/"
  [aa]="cairo|vulkan|assimp|embree|glm/|stb/"
  [ao]="cairo|vulkan|assimp|embree|glm/|stb/"
  [scene]="cairo|vulkan"
  [vk]="cairo|assimp|embree|glm/|stb/"
  [render]="cairo|assimp|embree"
  [deferred]="cairo|vulkan|assimp|embree"
  [gpu]="cairo|assimp|embree|glm/|stb/"
  [gpu_deferred]="cairo|assimp|embree|stb/"
  [eval]="vulkan/"
)
# The gpu folder's deferred family is its own target (ssfx_gpu_deferred, on gpu, deferred and
# render) so that ssfx_gpu stays free of scenes: these files are module gpu_deferred.
gpu_deferred_files=" $src/src/gpu/deferred_pass.cpp $src/include/ssfx/gpu/deferred.hpp $src/src/gpu/frame.cpp $src/include/ssfx/gpu/frame.hpp "
checked=0
for m in "${!allowed[@]}"; do
  for dir in "$src/src/$m" "$src/include/ssfx/$m"; do
    [ -d "$dir" ] || continue
    while IFS= read -r line; do
      file=${line%%:*}
      [[ $m == gpu && $gpu_deferred_files == *" $file "* ]] && continue
      inc=$(sed -E 's/.*#include *[<"]([^>"]+)[>"].*/\1/' <<<"$line")
      checked=$((checked + 1))
      if [[ $inc =~ ^ssfx/([a-z_]+)/ ]]; then
        dep=${BASH_REMATCH[1]}
        [[ " ${allowed[$m]} " == *" $dep "* ]] || bad "$file ($m) includes $inc ($dep is not below $m)"
      elif [[ $inc =~ ^src/([a-z_]+)/ ]]; then
        # Private headers are their module's; core's SIMD helpers serve the whole ssfx library.
        dep=${BASH_REMATCH[1]}
        [ "$dep" = "$m" ] || { [ "$dep" = core ] && [[ " core io aa ao " == *" $m "* ]]; } ||
          bad "$file ($m) includes another module's private header $inc"
      elif grep -Eq "^(${forbidden[$m]})" <<<"$inc"; then
        bad "$file ($m) includes $inc"
      fi
    done < <(grep -rHE '^#include' "$dir" --include=*.cpp --include=*.hpp --include=*.h)
  done
done
for file in $gpu_deferred_files; do
  [ -f "$file" ] || bad "$file: listed as module gpu_deferred but absent"
done
# shellcheck disable=SC2086
while IFS= read -r line; do
  file=${line%%:*}
  inc=$(sed -E 's/.*#include *[<"]([^>"]+)[>"].*/\1/' <<<"$line")
  checked=$((checked + 1))
  if [[ $inc =~ ^ssfx/([a-z_]+)/ ]]; then
    [[ " ${allowed[gpu_deferred]} " == *" ${BASH_REMATCH[1]} "* ]] || bad "$file (gpu_deferred) includes $inc"
  elif [[ $inc =~ ^src/([a-z_]+)/ ]]; then
    [ "${BASH_REMATCH[1]}" = gpu ] || bad "$file (gpu_deferred) includes another module's private header $inc"
  elif grep -Eq "^(${forbidden[gpu_deferred]})" <<<"$inc"; then
    bad "$file (gpu_deferred) includes $inc"
  fi
done < <(grep -HE '^#include' $gpu_deferred_files)

# The registries live in their families' modules (ssfx/aa/registry.hpp, ssfx/ao/registry.hpp,
# ssfx/deferred/registry.hpp); nothing is left at the top of the tree.
for file in "$src/src/registry.cpp" "$src/include/ssfx/registry.hpp"; do
  [ ! -e "$file" ] || bad "$file: the aa registry is aa's (include/ssfx/aa/registry.hpp, src/aa/registry.cpp)"
done

# One include style: a project header by its path from include/ ("ssfx/...") or from the
# repository root ("src/...", "apps/...", "tests/..."); generated SPIR-V ("shaders/*.inc")
# and Highway's own headers aside. Third-party headers take <...>.
while IFS= read -r line; do
  inc=$(sed -E 's/.*#include *"([^"]+)".*/\1/' <<<"$line")
  [[ $inc =~ ^(ssfx|src|apps|tests|bench|fuzz)/ || $inc =~ ^shaders/.*\.inc$ ]] ||
    bad "${line%%:*} includes \"$inc\" (project headers by their path from include/ or the root)"
done < <(grep -rHE '^#include *"' "$src/src" "$src/include" "$src/apps" "$src/tests" "$src/bench" "$src/fuzz" "$src/python" \
           --include=*.cpp --include=*.hpp --include=*.h --exclude-dir=node_modules)

# Link lines: "TARGET: lib;lib;..." per line.
declare -A nolink=(
  [ssfx]="cairo|vulkan|assimp|embree|ssfx_scene|ssfx_render|ssfx_eval|ssfx_deferred"
  [ssfx_scene]="vulkan|ssfx_render|ssfx_eval|cairo"
  [ssfx_deferred]="vulkan|ssfx_render|ssfx_eval|cairo"
  [ssfx_vk]="cairo|assimp|embree|ssfx_scene|ssfx_render|ssfx_eval|ssfx_deferred"
  [ssfx_render]="cairo|ssfx_eval|ssfx_deferred"
  [ssfx_gpu]="cairo|assimp|embree|ssfx_scene|ssfx_render|ssfx_eval|ssfx_deferred"
  [ssfx_gpu_deferred]="cairo|ssfx_eval"
)
while IFS= read -r line; do
  target=${line%%:*}
  libs=${line#*:}
  [ -n "${nolink[$target]:-}" ] || continue
  lower=$(tr '[:upper:]' '[:lower:]' <<<"$libs")
  if grep -Eq "(^|[;: ])[^;]*(${nolink[$target]})" <<<"$lower"; then
    bad "$target links $(grep -Eo "[^;]*(${nolink[$target]})[^;]*" <<<"$lower" | head -n 3 | tr '\n' ' ')"
  fi
done <"$links"
[ "$checked" -gt 100 ] || bad "only $checked includes found under $src: wrong source directory?"
[ "$fail" = 0 ] && echo "module rules: $checked includes and $(wc -l <"$links") link lines follow the rules"
exit $fail
