# Start-up time: the order in which the dynamic loader searches libraries.
#
# Debian's deal.II pulls about 200 shared libraries into every process
# (Trilinos, PETSc, OpenCASCADE, Gmsh, ...). At start-up the loader resolves
# some 340 000 symbol references, each by searching the libraries in load
# order until one defines the symbol; most of them point into a few large C++
# libraries (libdeal.ii alone takes 124 000), which a plain link loads 14th
# (deal.II), 45th (Gmsh) or 130th (OpenCASCADE's STEP reader). That search
# was 0.19 s of the 0.25 s that `signorini --help` took (perf, 2026-11-25).
#
# signorini_order_symbol_scope(TARGET) makes every executable that links
# TARGET name deal.II's heaviest libraries first, most-referenced first, so
# that they come first in the search. "Most referenced" is estimated from each
# library's own symbol relocations (its references to exported symbols,
# mostly its own: RELASZ / 24 - RELACOUNT of `readelf -d`), measured here at
# configure time on deal.II's dependency closure (`ldd`). The same libraries
# are loaded; only a symbol that several of them define can bind to another
# copy, and every reference to it moves together. Compared with the plain
# link under LD_BIND_NOW=1 LD_DEBUG=bindings (every reference bound at
# start, 2026-11-25), the non-C++ symbols that changed library were: LAPACK
# and BLAS routines (liblapack.so.3 and libblas.so.3 to libopenblas.so.0:
# Debian builds all three from one OpenBLAS, and dpotrf_, dgetrf_, dsytrf_
# and dsyevx_ disassemble to the same instructions in both), Open MPI's
# Fortran constants (mpi_fortran_in_place_, ...: a copy in PETSc; all
# references move together), SUNDIALS' shared routines, eight complex BLAS
# routines of ScaLAPACK and SCOTCH's error printers, which nothing here
# calls; and libcrypto's SCT_free, which the plain order bound to
# SuperLU_dist's function of that name, now binds to its own. C++ template
# and inline functions (defined weakly in many libraries, one definition by
# the language's rules) may bind to another copy. The sequential MUMPS that
# Ipopt links is not in deal.II's closure and so stays behind the parallel
# one (see CMakeLists.txt). tests/symbol_scope checks the order;
# doc/performance.md has the timings.
#
# Without ldd or readelf (another platform), or if the closure cannot be
# read, the link stays as it is.

function(signorini_order_symbol_scope _target)
  if(CMAKE_BUILD_TYPE STREQUAL "Debug")
    set(_libraries ${DEAL_II_LIBRARIES_DEBUG})
  else()
    set(_libraries ${DEAL_II_LIBRARIES_RELEASE})
  endif()
  list(GET _libraries 0 _deal_ii)
  find_program(_ldd ldd)
  find_program(_readelf readelf)
  if(NOT _ldd OR NOT _readelf OR NOT EXISTS "${_deal_ii}")
    message(STATUS "Library search order: left as linked (no ldd/readelf)")
    return()
  endif()

  execute_process(COMMAND ${_ldd} ${_deal_ii}
    OUTPUT_VARIABLE _ldd_output RESULT_VARIABLE _ldd_result ERROR_QUIET)
  if(NOT _ldd_result EQUAL 0)
    message(STATUS "Library search order: left as linked (ldd failed)")
    return()
  endif()
  string(REGEX MATCHALL "=> (/[^ ]+)" _matches "${_ldd_output}")
  set(_closure ${_deal_ii})
  foreach(_match ${_matches})
    string(REGEX REPLACE "^=> " "" _path "${_match}")
    list(APPEND _closure ${_path})
  endforeach()

  # One readelf call for the whole closure; its output names each file.
  execute_process(COMMAND ${_readelf} -d ${_closure}
    OUTPUT_VARIABLE _dynamic ERROR_QUIET)
  string(REPLACE ";" "," _dynamic "${_dynamic}")
  string(REGEX REPLACE "\n[ \t]*\n" "\n" _dynamic "${_dynamic}")
  string(REPLACE "\n" ";" _lines "${_dynamic}")

  set(_ranked)
  set(_file)
  set(_relasz 0)
  set(_relacount 0)
  foreach(_line ${_lines} "File: <end>")
    if(_line MATCHES "^File: (.*)$")
      set(_next "${CMAKE_MATCH_1}")
      if(_file)
        math(EXPR _symbolic "${_relasz} / 24 - ${_relacount}")
        # Below 200 references a library's place hardly matters.
        if(_symbolic GREATER_EQUAL 200)
          # Zero-padded so that a string sort is a numeric sort.
          string(LENGTH "${_symbolic}" _digits)
          math(EXPR _pad "10 - ${_digits}")
          string(REPEAT "0" ${_pad} _zeros)
          list(APPEND _ranked "${_zeros}${_symbolic}|${_file}")
        endif()
      endif()
      set(_file "${_next}")
      set(_relasz 0)
      set(_relacount 0)
    elseif(_line MATCHES "\\(RELASZ\\)[ \t]+([0-9]+)")
      set(_relasz ${CMAKE_MATCH_1})
    elseif(_line MATCHES "\\(RELACOUNT\\)[ \t]+([0-9]+)")
      set(_relacount ${CMAKE_MATCH_1})
    endif()
  endforeach()
  if(NOT _ranked)
    message(STATUS "Library search order: left as linked (no relocations read)")
    return()
  endif()
  list(SORT _ranked ORDER DESCENDING)

  set(_ordered)
  foreach(_entry ${_ranked})
    string(REGEX REPLACE "^[0-9]+\\|" "" _path "${_entry}")
    list(APPEND _ordered ${_path})
  endforeach()
  list(LENGTH _ordered _count)
  list(JOIN _ordered " " _joined)
  target_link_options(${_target} INTERFACE
    "SHELL:-Wl,--push-state,--no-as-needed ${_joined} -Wl,--pop-state")
  list(GET _ordered 0 _first)
  get_filename_component(_first_name "${_first}" NAME)
  message(STATUS "Library search order: ${_count} libraries first, "
    "most referenced first (${_first_name}, ...)")
endfunction()
