#!/bin/sh
# ffi/install.sh PREFIX: installs the C API of ke-friction for C, C++ and
# Fortran users into PREFIX (e.g. /usr/local, $HOME/.local, /opt/kefriction).
#
#   ffi/install.sh "$HOME/.local"
#
# It builds the release library first (`cargo build --release -p
# ke-friction-ffi`; nothing to do if it is current; CARGO_TARGET_DIR and
# CARGO are honoured), then installs:
#
#   PREFIX/lib/libkefriction.so, PREFIX/lib/libkefriction.a
#   PREFIX/include/kefriction.h
#   PREFIX/lib/pkgconfig/kefriction.pc            (pkg-config: kefriction)
#   PREFIX/lib/cmake/kefriction/kefrictionConfig.cmake (+ ConfigVersion)
#   PREFIX/share/kefriction/ke_friction.f90       (the Fortran module's source)
# and, if gfortran is on PATH (or FC names a Fortran compiler):
#   PREFIX/include/ke_friction.mod                (for `use ke_friction`)
#   PREFIX/lib/libkefriction_fortran.a            (the module's own procedures)
#   PREFIX/lib/pkgconfig/kefriction-fortran.pc    (pkg-config: kefriction-fortran)
# The .mod file only works with the compiler (and version) that made it;
# with another, compile share/kefriction/ke_friction.f90 yourself.
#
# Use (the shared library has no rpath of its own: give yours one):
#   C:      cc -O2 app.c $(pkg-config --cflags --libs kefriction) -Wl,-rpath,PREFIX/lib
#   static: cc -O2 app.c -IPREFIX/include PREFIX/lib/libkefriction.a -lpthread -ldl -lm
#   CMake:  find_package(kefriction CONFIG REQUIRED)
#           target_link_libraries(app PRIVATE kefriction::kefriction)
#           (configure with -DCMAKE_PREFIX_PATH=PREFIX
#           -DCMAKE_BUILD_TYPE=Release, or CMake compiles without -O; targets:
#           kefriction::kefriction (shared), kefriction::static,
#           kefriction::fortran (the module, when installed))
#   Fortran: gfortran -O2 app.f90 $(pkg-config --cflags --libs kefriction-fortran) -Wl,-rpath,PREFIX/lib
# (pkg-config finds PREFIX/lib/pkgconfig through PKG_CONFIG_PATH unless
# PREFIX is a system prefix.)
set -eu

usage() {
  echo "usage: $0 PREFIX   (installs lib/, include/, lib/pkgconfig/, lib/cmake/, share/ under PREFIX)" >&2
  exit 2
}
[ $# -eq 1 ] && [ -n "$1" ] || usage
case $1 in -h | --help) usage ;; esac

prefix=$1
mkdir -p "$prefix"
prefix=$(cd "$prefix" && pwd -P)
ffi=$(cd "$(dirname "$0")" && pwd -P)
cargo=${CARGO:-cargo}

# Build (cargo resolves a relative CARGO_TARGET_DIR against the caller's
# directory: stay in it), then ask cargo where the library is and which
# version it has.
"$cargo" build --release --quiet --manifest-path "$ffi/Cargo.toml" -p ke-friction-ffi
target=$("$cargo" metadata --format-version 1 --no-deps --manifest-path "$ffi/Cargo.toml" |
  sed -n 's/.*"target_directory":"\([^"]*\)".*/\1/p')
pkgid=$("$cargo" pkgid --manifest-path "$ffi/Cargo.toml" -p ke-friction-ffi)
version=${pkgid##*[#@]}
lib=$target/release
case $version in
  [0-9]*.[0-9]*.[0-9]*) ;;
  *) echo "install.sh: cannot read the crate's version from '$pkgid'" >&2; exit 1 ;;
esac
for f in libkefriction.so libkefriction.a; do
  [ -f "$lib/$f" ] || { echo "install.sh: $lib/$f is missing after the build (Linux only so far)" >&2; exit 1; }
done
major=${version%%.*}
minor=${version#*.}
minor=${minor%%.*}

install -d "$prefix/lib" "$prefix/include" "$prefix/lib/pkgconfig" \
  "$prefix/lib/cmake/kefriction" "$prefix/share/kefriction"
install -m 755 "$lib/libkefriction.so" "$prefix/lib/libkefriction.so"
install -m 644 "$lib/libkefriction.a" "$prefix/lib/libkefriction.a"
install -m 644 "$ffi/include/kefriction.h" "$prefix/include/kefriction.h"
install -m 644 "$ffi/fortran/ke_friction.f90" "$prefix/share/kefriction/ke_friction.f90"

# The Fortran module: its .mod for `use ke_friction`, and its few
# procedures of its own (kef_error_message, kef_version_string,
# kef_c_string) in a small static library.
fc=${FC:-gfortran}
fortran=no
if command -v "$fc" > /dev/null 2>&1; then
  scratch=$(mktemp -d)
  trap 'rm -rf "$scratch"' EXIT
  "$fc" -O2 -fPIC -c -J "$scratch" "$ffi/fortran/ke_friction.f90" -o "$scratch/ke_friction.o"
  rm -f "$scratch/libkefriction_fortran.a"
  ar rcs "$scratch/libkefriction_fortran.a" "$scratch/ke_friction.o"
  install -m 644 "$scratch/ke_friction.mod" "$prefix/include/ke_friction.mod"
  install -m 644 "$scratch/libkefriction_fortran.a" "$prefix/lib/libkefriction_fortran.a"
  fortran=yes
else
  rm -f "$prefix/include/ke_friction.mod" "$prefix/lib/libkefriction_fortran.a" \
    "$prefix/lib/pkgconfig/kefriction-fortran.pc"
  echo "install.sh: no Fortran compiler ($fc): the module's source only (share/kefriction/ke_friction.f90)" >&2
fi

# pkg-config.
cat > "$prefix/lib/pkgconfig/kefriction.pc" <<EOF
prefix=$prefix
exec_prefix=\${prefix}
libdir=\${exec_prefix}/lib
includedir=\${prefix}/include

Name: kefriction
Description: Kogut-Etsion static friction model of rough surfaces (C API of ke-friction)
Version: $version
Cflags: -I\${includedir}
Libs: -L\${libdir} -lkefriction
Libs.private: -lpthread -ldl -lm
EOF
if [ "$fortran" = yes ]; then
  cat > "$prefix/lib/pkgconfig/kefriction-fortran.pc" <<EOF
prefix=$prefix
exec_prefix=\${prefix}
libdir=\${exec_prefix}/lib
includedir=\${prefix}/include

Name: kefriction-fortran
Description: Fortran module ke_friction (use ke_friction) for ke-friction's C API
Version: $version
Requires: kefriction = $version
Cflags: -I\${includedir}
Libs: -L\${libdir} -lkefriction_fortran
EOF
fi

# CMake: find_package(kefriction CONFIG). Paths relative to this file, so
# the installed tree may be moved.
cat > "$prefix/lib/cmake/kefriction/kefrictionConfig.cmake" <<'EOF'
# kefriction: the C API of ke-friction (installed by ffi/install.sh).
#   find_package(kefriction CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE kefriction::kefriction)
# Targets: kefriction::kefriction (the shared library, libkefriction.so),
# kefriction::static (libkefriction.a), and kefriction::fortran (the
# Fortran module ke_friction, if it was installed).
get_filename_component(_kefriction_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
# The static library's system libraries, by name (not Threads::Threads:
# FindThreads needs C or C++, and a Fortran-only project may use this).
set(_kefriction_system_libs pthread ${CMAKE_DL_LIBS} m)

if(NOT TARGET kefriction::kefriction)
  add_library(kefriction::kefriction SHARED IMPORTED)
  set_target_properties(kefriction::kefriction PROPERTIES
    IMPORTED_LOCATION "${_kefriction_prefix}/lib/libkefriction.so"
    IMPORTED_NO_SONAME TRUE
    INTERFACE_INCLUDE_DIRECTORIES "${_kefriction_prefix}/include"
    INTERFACE_LINK_LIBRARIES "${_kefriction_system_libs}")
endif()

if(NOT TARGET kefriction::static)
  add_library(kefriction::static STATIC IMPORTED)
  set_target_properties(kefriction::static PROPERTIES
    IMPORTED_LOCATION "${_kefriction_prefix}/lib/libkefriction.a"
    IMPORTED_LINK_INTERFACE_LANGUAGES "C"
    INTERFACE_INCLUDE_DIRECTORIES "${_kefriction_prefix}/include"
    INTERFACE_LINK_LIBRARIES "${_kefriction_system_libs}")
endif()

if(NOT TARGET kefriction::fortran AND EXISTS "${_kefriction_prefix}/lib/libkefriction_fortran.a")
  add_library(kefriction::fortran STATIC IMPORTED)
  set_target_properties(kefriction::fortran PROPERTIES
    IMPORTED_LOCATION "${_kefriction_prefix}/lib/libkefriction_fortran.a"
    IMPORTED_LINK_INTERFACE_LANGUAGES "Fortran"
    INTERFACE_INCLUDE_DIRECTORIES "${_kefriction_prefix}/include"
    INTERFACE_LINK_LIBRARIES "kefriction::kefriction")
endif()

set(kefriction_INCLUDE_DIRS "${_kefriction_prefix}/include")
set(kefriction_LIBRARIES kefriction::kefriction)
unset(_kefriction_prefix)
unset(_kefriction_system_libs)
EOF
# Compatible: the same major version (and, before 1.0, the same minor), at
# least the version asked for; 64-bit only.
cat > "$prefix/lib/cmake/kefriction/kefrictionConfigVersion.cmake" <<EOF
set(PACKAGE_VERSION "$version")
if(PACKAGE_FIND_VERSION_RANGE)
  set(_kefriction_min "\${PACKAGE_FIND_VERSION_MIN}")
else()
  set(_kefriction_min "\${PACKAGE_FIND_VERSION}")
endif()
if(PACKAGE_VERSION VERSION_LESS _kefriction_min)
  set(PACKAGE_VERSION_COMPATIBLE FALSE)
elseif(PACKAGE_FIND_VERSION_RANGE AND PACKAGE_FIND_VERSION_RANGE_MAX STREQUAL "INCLUDE"
       AND PACKAGE_VERSION VERSION_GREATER PACKAGE_FIND_VERSION_MAX)
  set(PACKAGE_VERSION_COMPATIBLE FALSE)
elseif(PACKAGE_FIND_VERSION_RANGE AND PACKAGE_FIND_VERSION_RANGE_MAX STREQUAL "EXCLUDE"
       AND NOT PACKAGE_VERSION VERSION_LESS PACKAGE_FIND_VERSION_MAX)
  set(PACKAGE_VERSION_COMPATIBLE FALSE)
elseif(NOT PACKAGE_FIND_VERSION_RANGE AND PACKAGE_FIND_VERSION
       AND (NOT PACKAGE_FIND_VERSION_MAJOR EQUAL $major
            OR ($major EQUAL 0 AND NOT PACKAGE_FIND_VERSION_MINOR EQUAL $minor)))
  set(PACKAGE_VERSION_COMPATIBLE FALSE)
else()
  set(PACKAGE_VERSION_COMPATIBLE TRUE)
  if(PACKAGE_FIND_VERSION STREQUAL PACKAGE_VERSION)
    set(PACKAGE_VERSION_EXACT TRUE)
  endif()
endif()
unset(_kefriction_min)
if(NOT "\${CMAKE_SIZEOF_VOID_P}" STREQUAL "" AND NOT "\${CMAKE_SIZEOF_VOID_P}" STREQUAL "8")
  set(PACKAGE_VERSION "\${PACKAGE_VERSION} (64-bit)")
  set(PACKAGE_VERSION_UNSUITABLE TRUE)
endif()
EOF

echo "installed kefriction $version into $prefix (Fortran module: $fortran)"
