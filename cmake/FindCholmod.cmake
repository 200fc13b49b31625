# CHOLMOD from SuiteSparse (Debian libsuitesparse-dev). Defines Cholmod::Cholmod.
find_path(Cholmod_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(Cholmod_LIBRARY NAMES cholmod)
find_library(Cholmod_SuiteSparseConfig_LIBRARY NAMES suitesparseconfig)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Cholmod
  REQUIRED_VARS Cholmod_LIBRARY Cholmod_SuiteSparseConfig_LIBRARY Cholmod_INCLUDE_DIR)
if(Cholmod_FOUND AND NOT TARGET Cholmod::Cholmod)
  add_library(Cholmod::Cholmod INTERFACE IMPORTED)
  set_target_properties(Cholmod::Cholmod PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${Cholmod_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${Cholmod_LIBRARY};${Cholmod_SuiteSparseConfig_LIBRARY}")
endif()
