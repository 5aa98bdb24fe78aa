# The genmesh program, run as a user would (exit codes, messages, --json).
if(TARGET genmesh_cli AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/test_cli.cpp)
  genmesh_test(test_cli)
  target_compile_definitions(test_cli PRIVATE GENMESH_CLI="$<TARGET_FILE:genmesh_cli>"
                             GENMESH_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  add_dependencies(test_cli genmesh_cli)
endif()
