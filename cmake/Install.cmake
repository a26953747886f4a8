# The model as a library: namespaced targets, the install rules and the CMake package config.
#
#   vbim::kernel vbim::iop vbim::ipu_core vbim::ipu vbim::gs vbim::streams vbim::ee vbim::player
#                   the model's libraries (the C++ standard library and threads only)
#   vbim::config    TOML platform configs and fault plans (links toml++ through pkg-config)
#   vbim::model     every model library
#   vbim::testing   vbim::model + vbim::config: what a stall-injection test suite links
#
# The same names work after find_package(vbim) and after add_subdirectory(vbim). A VBIM_MODEL_ONLY
# build has no configuration layer: it defines and installs the model and vbim::model only, with no
# vbim::config and no vbim::testing (a suite that writes TOML then fails at configure time, not at
# compile time).
#
# `cmake --install <build> --prefix <dir>` puts:
#   include/vbim/<folder>/*.hpp        headers of the model and config folders, included as
#                                      "player/scenario.hpp" with include/vbim on the path
#   lib/libvbim_*.a                    the libraries
#   lib/cmake/vbim/                    vbimConfig.cmake, vbimConfigVersion.cmake, the exported targets
#   share/vbim/samples/*.vbim          the sample streams (VBIM_SAMPLES_DIR in the package config)
# and bin/vbim, bin/vbim-full (cli/CMakeLists.txt) in a full build.

include(CMakePackageConfigHelpers)

# Off when vbim is built inside another project (add_subdirectory): its install is the parent's.
option(VBIM_INSTALL "Install the model library, its headers and the CMake package config" ${PROJECT_IS_TOP_LEVEL})

get_property(_vbim_model_targets GLOBAL PROPERTY VBIM_MODEL_TARGETS)

# vbim_<name> is vbim::<name> for both kinds of user.
foreach(_target IN LISTS _vbim_model_targets)
  string(REGEX REPLACE "^vbim_" "" _name ${_target})
  set_target_properties(${_target} PROPERTIES EXPORT_NAME ${_name})
  add_library(vbim::${_name} ALIAS ${_target})
endforeach()

add_library(vbim_model INTERFACE)
target_link_libraries(vbim_model INTERFACE ${_vbim_model_targets})
set_target_properties(vbim_model PROPERTIES EXPORT_NAME model)
add_library(vbim::model ALIAS vbim_model)

if(TARGET vbim_config)
  set_target_properties(vbim_config PROPERTIES EXPORT_NAME config)
  add_library(vbim::config ALIAS vbim_config)
  add_library(vbim_testing INTERFACE)
  target_link_libraries(vbim_testing INTERFACE vbim_model vbim_config)
  set_target_properties(vbim_testing PROPERTIES EXPORT_NAME testing)
  add_library(vbim::testing ALIAS vbim_testing)
endif()

if(NOT VBIM_INSTALL)
  return()
endif()

set(VBIM_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/vbim)
set(VBIM_INSTALL_SAMPLESDIR ${CMAKE_INSTALL_DATADIR}/vbim/samples)

# Headers: every folder that holds a model library (and config/), keeping the folder paths. Some of
# those folders also hold code outside the model, with its own targets and third-party includes;
# their headers stay out (scripts/check-model.sh compiles every installed model header without any
# third-party header reachable, scripts/check-install.sh checks that each include resolves).
set(_vbim_header_folders "")
foreach(_target IN LISTS _vbim_model_targets ITEMS vbim_config)
  if(TARGET ${_target})
    get_target_property(_dir ${_target} SOURCE_DIR)
    file(RELATIVE_PATH _folder ${PROJECT_SOURCE_DIR} ${_dir})
    list(APPEND _vbim_header_folders ${_folder})
  endif()
endforeach()
list(REMOVE_DUPLICATES _vbim_header_folders)
foreach(_folder IN LISTS _vbim_header_folders)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${_folder}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/vbim/${_folder}
          FILES_MATCHING PATTERN "*.hpp"
          PATTERN "blend_simd.hpp" EXCLUDE  # gs/: Highway kernels
          PATTERN "simd" EXCLUDE            # ipu/simd/, runtime/simd/: Highway kernels and their dispatch
          PATTERN "authoring" EXCLUDE       # streams/authoring/: FFmpeg, OpenImageIO
          PATTERN "disc" EXCLUDE            # streams/disc/: disc images (xorriso, the player)
          PATTERN "outputs" EXCLUDE         # sweep/outputs/: the tables and figures (nlohmann_json, PLplot)
          PATTERN "decode" EXCLUDE          # streams/decode/: vbim decode's library (imageio, Highway)
          PATTERN "info" EXCLUDE            # streams/info/: vbim info's library (nlohmann_json, disc images)
          PATTERN "toml_document.hpp" EXCLUDE  # config/: internal, toml++ stays inside config
          PATTERN "samples" EXCLUDE)        # streams/samples/: no headers (the streams go to share/)
endforeach()

# Two export sets, so that a user of the model alone never needs toml++ (vbimConfig.cmake loads the
# second only when the configuration layer is wanted).
install(TARGETS ${_vbim_model_targets} vbim_model EXPORT vbimModelTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT vbimModelTargets NAMESPACE vbim:: DESTINATION ${VBIM_INSTALL_CMAKEDIR})
if(TARGET vbim_config)
  set(VBIM_PACKAGE_HAS_CONFIG TRUE)
  install(TARGETS vbim_config vbim_testing EXPORT vbimConfigTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(EXPORT vbimConfigTargets NAMESPACE vbim:: DESTINATION ${VBIM_INSTALL_CMAKEDIR})
else()
  set(VBIM_PACKAGE_HAS_CONFIG FALSE)
endif()

# The C99 reference of docs/porting.md ("A C reference"): one header, no dependency.
install(FILES ${PROJECT_SOURCE_DIR}/ref/vbim_ref.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/vbim)

file(GLOB _vbim_samples ${PROJECT_SOURCE_DIR}/streams/samples/*.vbim)
install(FILES ${_vbim_samples} DESTINATION ${VBIM_INSTALL_SAMPLESDIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/vbimConfig.cmake.in ${PROJECT_BINARY_DIR}/vbimConfig.cmake
                              INSTALL_DESTINATION ${VBIM_INSTALL_CMAKEDIR} PATH_VARS VBIM_INSTALL_SAMPLESDIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/vbimConfigVersion.cmake VERSION ${PROJECT_VERSION}
                                 COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/vbimConfig.cmake ${PROJECT_BINARY_DIR}/vbimConfigVersion.cmake
        DESTINATION ${VBIM_INSTALL_CMAKEDIR})
