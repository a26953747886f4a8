# Finds every dependency once, and stops with the Debian package to install when one is missing.
# scripts/setup.sh installs all of them.

find_package(PkgConfig QUIET)
if(NOT PKG_CONFIG_FOUND AND NOT VBIM_MODEL_ONLY)
  message(FATAL_ERROR "pkg-config not found: apt-get install pkg-config (or run scripts/setup.sh)")
endif()

# vbim_require_config(<find_package name> <debian package> [COMPONENTS ...])
macro(vbim_require_config name debpkg)
  find_package(${name} CONFIG QUIET ${ARGN})
  if(NOT ${name}_FOUND)
    message(FATAL_ERROR "${name} not found: apt-get install ${debpkg} (or run scripts/setup.sh as root)")
  endif()
endmacro()

# vbim_require_pkgconfig(<prefix> <debian packages> <pkg-config modules...>)
macro(vbim_require_pkgconfig prefix debpkgs)
  pkg_check_modules(${prefix} QUIET IMPORTED_TARGET ${ARGN})
  if(NOT ${prefix}_FOUND)
    message(FATAL_ERROR "pkg-config modules '${ARGN}' not found: apt-get install ${debpkgs} (or run scripts/setup.sh as root)")
  endif()
endmacro()

# The model needs none of these: a model-only build skips them (VBIM_MODEL_ONLY).
if(NOT VBIM_MODEL_ONLY)
  vbim_require_config(CLI11 libcli11-dev)
  vbim_require_config(nlohmann_json nlohmann-json3-dev)
  vbim_require_pkgconfig(TOMLPP libtomlplusplus-dev tomlplusplus)
  # SHA-256 digests of a run's inputs, recorded in stats.json (cli/provenance.cpp).
  vbim_require_pkgconfig(LIBCRYPTO libssl-dev libcrypto)
  vbim_require_pkgconfig(LIBAV "libavcodec-dev libavformat-dev libavutil-dev libswscale-dev"
                         libavformat libavcodec libavutil libswscale)
  vbim_require_pkgconfig(LIBMPEG2 libmpeg2-4-dev libmpeg2 libmpeg2convert)
  # `vbim author --iso` runs xorriso to write disc images (streams/disc/iso_writer.cpp).
  find_program(VBIM_XORRISO xorriso)
  if(NOT VBIM_XORRISO)
    message(FATAL_ERROR "xorriso not found: apt-get install xorriso (or run scripts/setup.sh as root)")
  endif()
  vbim_require_pkgconfig(OSMESA libosmesa6-dev osmesa)
  vbim_require_pkgconfig(HWY libhwy-dev libhwy)
  # Highway's headers without libhwy.so: the product's kernels dispatch through runtime/simd/targets.hpp,
  # because loading libhwy.so costs every process 4-6 ms of CPU at start-up (its timer calibration, docs/sweeps.md). Only
  # tests and benchmarks that compare with Highway's own target detection link PkgConfig::HWY.
  add_library(vbim_hwy_headers INTERFACE)
  target_include_directories(vbim_hwy_headers INTERFACE ${HWY_INCLUDE_DIRS})
  target_compile_options(vbim_hwy_headers INTERFACE ${HWY_CFLAGS_OTHER})
  vbim_require_config(glm libglm-dev)
  # Image output of the lean `vbim` tool (imageio/, its lean part): small libraries, not OpenImageIO.
  vbim_require_pkgconfig(PNG libpng-dev libpng)
  # The checksums of level-0 PNGs, which imageio/stored_png.cpp writes without libpng.
  vbim_require_pkgconfig(DEFLATE libdeflate-dev libdeflate)
  vbim_require_pkgconfig(OPENEXR libopenexr-dev OpenEXR)

  # Plots (plots/): PLplot and its cairo driver (PNG and SVG devices). PLplot loads the driver at run
  # time from its drivers directory, so a missing driver package would only show when a plot is drawn.
  vbim_require_pkgconfig(PLPLOT "libplplot-dev plplot-driver-cairo" plplot)
  pkg_get_variable(PLPLOT_DRV_DIR plplot drvdir)
  if(NOT EXISTS "${PLPLOT_DRV_DIR}/cairo.driver_info")
    message(FATAL_ERROR "PLplot's cairo driver not found in '${PLPLOT_DRV_DIR}': apt-get install plplot-driver-cairo (or run scripts/setup.sh as root)")
  endif()

  # OpenImageIO through pkg-config: Debian 12's CMake config lists /usr/include/opencv4 and the
  # openimageio-tools binaries, neither of which libopenimageio-dev installs, so its generate step
  # fails (docs/dependencies.md#openimageio-cmake-config).
  vbim_require_pkgconfig(OIIO libopenimageio-dev OpenImageIO)
  # DEMs in and georeferenced debug layers out (lighting/dem_reader, lighting/geotiff_layers).
  vbim_require_pkgconfig(GDAL libgdal-dev gdal)
endif()

if(VBIM_BUILD_TESTS)
  find_package(GTest QUIET)
  if(NOT GTest_FOUND)
    message(FATAL_ERROR "GoogleTest not found: apt-get install libgtest-dev libgmock-dev (or run scripts/setup.sh as root)")
  endif()
  include(GoogleTest)
endif()
if(VBIM_BUILD_BENCH AND NOT VBIM_MODEL_ONLY)
  vbim_require_config(benchmark libbenchmark-dev)
  # Optional: bench_scheduler_cost compares the kernel with SystemC 2.3.4 when it is installed.
  if(PKG_CONFIG_FOUND)
    pkg_check_modules(SYSTEMC QUIET IMPORTED_TARGET systemc)
  endif()
  if(NOT SYSTEMC_FOUND)
    message(STATUS "SystemC not found (apt-get install libsystemc-dev): bench_scheduler_cost skips its comparison")
  endif()
endif()
find_package(Threads REQUIRED)
