# The GPU ensemble engine (kernels/cuda/): built when nvcc is found (CASKDEM_WITH_CUDA=AUTO), or
# asked for (ON), or left out (OFF). Without it caskdem builds and runs on the CPU alone, and
# `--device cuda` says why it cannot.
#
# Bit for bit with the CPU (kernels/cuda/cuda_lane_device.cu): -fmad=false (no contracted
# multiply-add, as -ffp-contract=off on the host), IEEE division and square root, subnormals
# kept. Machine code for Hopper (sm_90: the H100 and H200) with its PTX beside it, and the CUDA
# runtime linked statically, so that a binary built here runs on a machine that has the driver
# alone.

set(CASKDEM_WITH_CUDA "AUTO" CACHE STRING "Build the GPU ensemble engine: ON, OFF or AUTO (on when nvcc is found)")
set(CASKDEM_CUDA_ARCHITECTURES "90" CACHE STRING "CUDA architectures of the GPU engine (90: Hopper)")

set(CASKDEM_HAVE_CUDA OFF)
if(CASKDEM_WITH_CUDA STREQUAL "AUTO" AND (CASKDEM_SANITIZE OR CASKDEM_BUILD_FUZZERS))
  # The sanitizers instrument host code that nvcc's host compiler would build without them; the
  # engine's host side (src/ensemble/device_runner.cpp, kernels/host_lane_device.cpp) is still
  # built and checked there.
  message(STATUS "caskdem: sanitizer build, GPU engine left out")
elseif(CASKDEM_WITH_CUDA STREQUAL "AUTO" OR CASKDEM_WITH_CUDA)
  include(CheckLanguage)
  check_language(CUDA)
  if(CMAKE_CUDA_COMPILER)
    set(CMAKE_CUDA_ARCHITECTURES ${CASKDEM_CUDA_ARCHITECTURES})
    # The runtime comes as CUDA::cudart_static (kernels/CMakeLists.txt), by its full path.
    set(CMAKE_CUDA_RUNTIME_LIBRARY None)
    enable_language(CUDA)
    # CMake 3.25 knows no C++20 dialect flag for nvcc (nvcc 12 and later have it).
    if(NOT DEFINED CMAKE_CUDA20_STANDARD_COMPILE_OPTION)
      set(CMAKE_CUDA20_STANDARD_COMPILE_OPTION "-std=c++20")
      set(CMAKE_CUDA20_EXTENSION_COMPILE_OPTION "-std=c++20")
    endif()
    find_package(CUDAToolkit REQUIRED)
    set(CASKDEM_HAVE_CUDA ON)
    message(STATUS "caskdem: GPU engine with nvcc ${CMAKE_CUDA_COMPILER_VERSION}, architectures ${CMAKE_CUDA_ARCHITECTURES}")
  elseif(NOT CASKDEM_WITH_CUDA STREQUAL "AUTO")
    message(FATAL_ERROR "CASKDEM_WITH_CUDA=ON but no CUDA compiler (nvcc) was found")
  else()
    message(STATUS "caskdem: no nvcc found, GPU engine left out")
  endif()
endif()

# The flags every CUDA source of the engine is built with.
set(CASKDEM_CUDA_FLAGS
  -fmad=false -prec-div=true -prec-sqrt=true -ftz=false
  # std::array, std::bit_cast and std::min/max in the step are constexpr host functions.
  --expt-relaxed-constexpr
  # A host function called from device code is only a warning in a template: make it an error.
  --diag-error=20011,20013,20014,20015
  -Xcompiler=-ffp-contract=off,-fno-fast-math,-Wall,-Wextra)
