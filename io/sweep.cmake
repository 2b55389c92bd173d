# Parameter sweeps (io/sweep_*): grids, points, the results folder, local threads, and the
# distribution over MPI ranks when an MPI library is found (option TRIBO_WITH_MPI, on by
# default when found; Debian: libopenmpi-dev openmpi-bin). Included from io/CMakeLists.txt.
find_package(Threads REQUIRED)
find_package(MPI COMPONENTS CXX QUIET)
option(TRIBO_WITH_MPI "Spread 'tribo sweep' over MPI ranks (needs an MPI library)" ${MPI_CXX_FOUND})

add_library(tribo_sweep STATIC
  ${CMAKE_CURRENT_LIST_DIR}/sweep_grid.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sweep_settle.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sweep_point.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sweep_results.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sweep_progress.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sweep_runner.cpp
)
target_include_directories(tribo_sweep PUBLIC ${PROJECT_SOURCE_DIR})
target_link_libraries(tribo_sweep PUBLIC tribo_io Threads::Threads
                      PRIVATE nlohmann_json::nlohmann_json)

if(TRIBO_WITH_MPI)
  if(NOT MPI_CXX_FOUND)
    message(FATAL_ERROR "TRIBO_WITH_MPI is ON but no MPI library was found "
                        "(Debian: libopenmpi-dev openmpi-bin), or configure with -DTRIBO_WITH_MPI=OFF")
  endif()
  target_sources(tribo_sweep PRIVATE ${CMAKE_CURRENT_LIST_DIR}/sweep_mpi.cpp)
  target_link_libraries(tribo_sweep PUBLIC MPI::MPI_CXX)
  # The C API only (no C++ bindings in the code).
  target_compile_definitions(tribo_sweep PRIVATE OMPI_SKIP_MPICXX MPICH_SKIP_MPICXX
                             PUBLIC TRIBO_WITH_MPI)
endif()
message(STATUS "tribo sweep over MPI ranks: ${TRIBO_WITH_MPI}")
