# Oscillation analysis for run summaries (std only); included from io/CMakeLists.txt.
add_library(tribo_oscillation STATIC ${CMAKE_CURRENT_LIST_DIR}/oscillation_summary.cpp)
target_include_directories(tribo_oscillation PUBLIC ${PROJECT_SOURCE_DIR})
