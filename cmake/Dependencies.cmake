# Finds every third-party library hpcontact uses; all come from Debian 12 packages
# (cmake/quickstart.sh installs them). Nothing is vendored or downloaded.
find_package(PkgConfig REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(GSL REQUIRED)
find_package(MPI REQUIRED COMPONENTS C CXX)
find_package(Threads REQUIRED)  # the interpolation norm's quadrature nodes run on threads
pkg_check_modules(PETSC REQUIRED IMPORTED_TARGET PETSc>=3.18)
pkg_check_modules(SLEPC REQUIRED IMPORTED_TARGET SLEPc>=3.18)
pkg_check_modules(MUPARSER REQUIRED IMPORTED_TARGET muparser)
find_package(fmt REQUIRED)
find_package(tomlplusplus REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json REQUIRED)

# CHOLMOD (SuiteSparse): Debian 12 ships no CMake config for it, so find header and libraries.
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
add_library(hpcontact_cholmod INTERFACE)
target_include_directories(hpcontact_cholmod INTERFACE ${CHOLMOD_INCLUDE_DIR})
target_link_libraries(hpcontact_cholmod INTERFACE ${CHOLMOD_LIBRARY} ${SUITESPARSECONFIG_LIBRARY})

# PT-Scotch (libptscotch-dev, which PETSc's MatPartitioning calls): hpcontact resets its random
# generator before each partition, so that the same graph always gets the same parts.
find_path(PTSCOTCH_INCLUDE_DIR ptscotch.h PATH_SUFFIXES scotch REQUIRED)
find_library(PTSCOTCH_LIBRARY ptscotch REQUIRED)
add_library(hpcontact_ptscotch INTERFACE)
target_include_directories(hpcontact_ptscotch INTERFACE ${PTSCOTCH_INCLUDE_DIR})
target_link_libraries(hpcontact_ptscotch INTERFACE ${PTSCOTCH_LIBRARY})

# The Gmsh API (libgmsh-dev) reads mesh files. It is loaded at run time (mesh/gmsh_api.hpp), so
# only its header is used at build time, and the library's real file is where it is looked for
# first.
find_path(GMSH_INCLUDE_DIR gmshc.h REQUIRED)
find_library(GMSH_LIBRARY gmsh REQUIRED)
get_filename_component(GMSH_LIBRARY_FILE "${GMSH_LIBRARY}" REALPATH)
add_library(hpcontact_gmsh INTERFACE)
target_include_directories(hpcontact_gmsh INTERFACE ${GMSH_INCLUDE_DIR})
target_compile_definitions(hpcontact_gmsh INTERFACE HPCONTACT_GMSH_LIBRARY="${GMSH_LIBRARY_FILE}")
target_link_libraries(hpcontact_gmsh INTERFACE ${CMAKE_DL_LIBS})
