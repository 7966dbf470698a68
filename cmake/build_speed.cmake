# Compile time: what a fresh build and the test suite spend compiling.
#
# Measured on the 2-core machine (2026-11-26, one file at a time, see
# doc/building.md): almost all of a translation unit's time is spent in
# deal.II's headers, not in our code. source/first_error.cc includes only
# <deal.II/base/mpi.h>, 360 000 preprocessed lines, and took 7.0 s; the
# largest files (two_body.cc, simulator.cc) 23-25 s. Two things cut it:
#
# 1. No debug information by default. Debian's deal.II exports "-g" among
#    its release flags (DEAL_II_CXX_FLAGS_RELEASE), so every object carried
#    full DWARF for all of deal.II's inline code: about 15% of each file's
#    compile time and most of the link time. SIGNORINI_DEBUG_INFO=ON keeps
#    it (for gdb or perf with source lines).
#
# 2. One precompiled header of the deal.II headers that most files use,
#    built once (signorini_pch) and reused by the library, the executables
#    and the unit tests that include deal.II. GCC accepts it only where the
#    compile options and the macros it was built with are the same; every
#    target here gets deal.II's flags from deal_ii_setup_target, and the
#    macros that targets add (SIGNORINI_*, SOURCE_DIR) do not occur in
#    deal.II's headers. -Winvalid-pch makes a rejected header visible.
#    SIGNORINI_PRECOMPILED_HEADERS=OFF builds without it.

option(SIGNORINI_DEBUG_INFO
  "Compile with debug information (-g); off by default: it costs compile and link time" OFF)
option(SIGNORINI_PRECOMPILED_HEADERS
  "Precompile the deal.II headers that most files include" ON)

if(NOT SIGNORINI_DEBUG_INFO)
  foreach(_var DEAL_II_CXX_FLAGS DEAL_II_CXX_FLAGS_RELEASE DEAL_II_CXX_FLAGS_DEBUG
               DEAL_II_LINKER_FLAGS DEAL_II_LINKER_FLAGS_RELEASE)
    # -g, -g1..-g3, -ggdb: whole words only (not -grecord-gcc-switches).
    string(REGEX REPLACE "(^| )-g(gdb)?[0-3]?( |$)" " " ${_var} "${${_var}}")
  endforeach()
endif()

# The deal.II headers of the precompiled header: those that the library's
# files include most (grep -h '#include <deal.II' include source | sort |
# uniq -c), and the heavy ones behind them (DataOut, the Trilinos wrappers,
# FEValues, the distributed triangulation).
set(SIGNORINI_PRECOMPILED_HEADER_LIST
  <deal.II/base/mpi.h>
  <deal.II/base/parameter_handler.h>
  <deal.II/base/conditional_ostream.h>
  <deal.II/base/timer.h>
  <deal.II/base/quadrature_lib.h>
  <deal.II/base/tensor.h>
  <deal.II/base/point.h>
  <deal.II/base/index_set.h>
  <deal.II/base/utilities.h>
  <deal.II/lac/vector.h>
  <deal.II/lac/full_matrix.h>
  <deal.II/lac/affine_constraints.h>
  <deal.II/lac/trilinos_vector.h>
  <deal.II/lac/trilinos_sparse_matrix.h>
  <deal.II/lac/trilinos_sparsity_pattern.h>
  <deal.II/distributed/tria.h>
  <deal.II/dofs/dof_handler.h>
  <deal.II/dofs/dof_tools.h>
  <deal.II/fe/fe_values.h>
  <deal.II/fe/fe_q.h>
  <deal.II/fe/fe_system.h>
  <deal.II/fe/mapping_q.h>
  <deal.II/grid/grid_tools.h>
  <deal.II/numerics/data_out.h>
  <deal.II/numerics/rtree.h>
  <string>
  <vector>
  <map>
  <memory>
  <functional>
  <iostream>
  <fstream>
  <sstream>
  <iomanip>
  <algorithm>
  <cmath>)

# The precompiled header's own target: an object library of one empty file
# with deal.II's flags and nothing else. GCC uses a precompiled header only
# where every macro defined when it was built is defined the same way, so
# it is not built by a target with definitions of its own (the library's
# signorini_lib_EXPORTS and SIGNORINI_SOURCE_DIR were missing in the
# executables, which then parsed the headers again).
function(signorini_add_precompiled_header_target)
  if(SIGNORINI_PRECOMPILED_HEADERS)
    set(_source ${CMAKE_BINARY_DIR}/signorini_pch.cc)
    if(NOT EXISTS ${_source})
      file(WRITE ${_source} "// The precompiled header's own translation unit.\n")
    endif()
    add_library(signorini_pch OBJECT ${_source})
    deal_ii_setup_target(signorini_pch)
    target_precompile_headers(signorini_pch PRIVATE ${SIGNORINI_PRECOMPILED_HEADER_LIST})
  endif()
endfunction()

# Let TARGET reuse the precompiled header (after deal_ii_setup_target).
function(signorini_reuse_precompiled_headers _target)
  if(SIGNORINI_PRECOMPILED_HEADERS)
    target_precompile_headers(${_target} REUSE_FROM signorini_pch)
    target_compile_options(${_target} PRIVATE -Winvalid-pch)
  endif()
endfunction()

# The library's headers that include no deal.II header.
set(SIGNORINI_LIGHT_HEADERS "atomic_file|json|rank_agreement|mpi_environment|pattern_hash")

# Whether FILE includes deal.II or a library header other than the light
# ones (directly: a light header includes no deal.II header either).
function(signorini_includes_deal_ii _result _file)
  file(STRINGS "${_file}" _includes REGEX "#include [<\"](deal\\.II|signorini)/")
  list(FILTER _includes EXCLUDE REGEX "/(${SIGNORINI_LIGHT_HEADERS})\\.h")
  if(_includes)
    set(${_result} TRUE PARENT_SCOPE)
  else()
    set(${_result} FALSE PARENT_SCOPE)
  endif()
endfunction()

# Files that include no deal.II header compile in under 2 s; loading the
# precompiled header (about 1.4 s) would make them slower.
function(signorini_skip_precompiled_headers_where_light)
  foreach(_file IN LISTS ARGN)
    signorini_includes_deal_ii(_heavy "${_file}")
    if(NOT _heavy)
      set_source_files_properties(${_file} PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
    endif()
  endforeach()
endfunction()
