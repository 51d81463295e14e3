# All dependencies come from Debian 12 packages (scripts/install-deps.sh).

find_package(Eigen3 3.4 REQUIRED NO_MODULE)

# Debian's xsimd 8.1 export lists xtl as a link dependency although xsimd 8 needs nothing
# from it; an empty imported target stops the link from asking for -lxtl.
if(NOT TARGET xtl)
  add_library(xtl INTERFACE IMPORTED)
endif()
find_package(xsimd 8.1 REQUIRED)

find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(HDF5 REQUIRED COMPONENTS C)
find_package(tomlplusplus REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3.11 REQUIRED)
find_package(NLopt REQUIRED)
find_package(Boost 1.74 REQUIRED)

find_path(RANDOM123_INCLUDE_DIR Random123/philox.h REQUIRED)
add_library(random123 INTERFACE IMPORTED)
target_include_directories(random123 INTERFACE ${RANDOM123_INCLUDE_DIR})

add_library(hdf5_c INTERFACE IMPORTED)
target_include_directories(hdf5_c INTERFACE ${HDF5_INCLUDE_DIRS})
target_link_libraries(hdf5_c INTERFACE ${HDF5_C_LIBRARIES})
target_compile_definitions(hdf5_c INTERFACE ${HDF5_DEFINITIONS})

if(CASKDEM_WITH_MPI STREQUAL "AUTO")
  find_package(MPI COMPONENTS CXX)
  set(CASKDEM_HAVE_MPI ${MPI_CXX_FOUND})
elseif(CASKDEM_WITH_MPI)
  find_package(MPI REQUIRED COMPONENTS CXX)
  set(CASKDEM_HAVE_MPI ON)
else()
  set(CASKDEM_HAVE_MPI OFF)
endif()

# The plotting scripts run under Debian's interpreter, which has python3-matplotlib and
# python3-h5py; the python3 first on PATH may be another one without them.
set(CASKDEM_PYTHON "/usr/bin/python3" CACHE FILEPATH "Python interpreter with matplotlib and h5py")
