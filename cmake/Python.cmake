# The Python module (src/python/): built with Debian's pybind11 for Debian's interpreter
# (CASKDEM_PYTHON, /usr/bin/python3), from the same libraries as the command line, which are then
# built position-independent so that the module can hold them. Not in sanitizer and fuzzer
# builds (an instrumented module would need the sanitizer's runtime preloaded into Python).

set(CASKDEM_WITH_PYTHON "AUTO" CACHE STRING
    "Build the Python module: ON, OFF or AUTO (on when pybind11 and Python's headers are found)")
set(CASKDEM_HAVE_PYTHON OFF)
if(CASKDEM_SANITIZE OR CASKDEM_BUILD_FUZZERS)
  if(CASKDEM_WITH_PYTHON STREQUAL "ON")
    message(FATAL_ERROR "CASKDEM_WITH_PYTHON=ON: the Python module is not built with sanitizers or fuzzers")
  endif()
elseif(NOT CASKDEM_WITH_PYTHON STREQUAL "OFF")
  set(Python_EXECUTABLE ${CASKDEM_PYTHON})
  set(PYBIND11_FINDPYTHON ON)
  if(CASKDEM_WITH_PYTHON STREQUAL "AUTO")
    find_package(Python 3.9 COMPONENTS Interpreter Development.Module)
    if(Python_FOUND)
      find_package(pybind11 2.6 CONFIG QUIET)
    endif()
    if(NOT pybind11_FOUND)
      message(STATUS "caskdem: no Python module (needs python3-dev and python3-pybind11; scripts/install-deps.sh)")
    endif()
  else()
    find_package(Python 3.9 REQUIRED COMPONENTS Interpreter Development.Module)
    find_package(pybind11 2.6 CONFIG REQUIRED)
  endif()
  if(pybind11_FOUND)
    set(CASKDEM_HAVE_PYTHON ON)
    set(CMAKE_POSITION_INDEPENDENT_CODE ON)
    # cmake --install: where Debian's interpreter looks under the prefix (/usr/local/lib/python3.11/dist-packages)
    set(CASKDEM_PYTHON_INSTALL_DIR "lib/python${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}/dist-packages" CACHE STRING
        "Where cmake --install puts the caskdem package, under the prefix")
  endif()
endif()
