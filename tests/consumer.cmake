# Installs genmesh into a scratch prefix, then configures, builds and runs an
# outside project that finds it with find_package(genmesh CONFIG REQUIRED).
add_test(NAME install.consumer
  COMMAND ${CMAKE_COMMAND}
    -DGENMESH_BINARY_DIR=${PROJECT_BINARY_DIR}
    -DCONSUMER_SOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/consumer
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/consumer_work
    -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}
    -P ${CMAKE_CURRENT_SOURCE_DIR}/consumer_test.cmake)
set_tests_properties(install.consumer PROPERTIES TIMEOUT 300)

# The same with Clang, and the examples built with it as a user's sources,
# -Wall -Wextra -Wpedantic -Werror: genmesh is header-only, so every header a
# user includes must compile cleanly with both compilers (Clang 14 rejected
# collapse.h once, in session 18, and warned in -Wall until session 20).
# scripts/run.sh test installs clang; without it the test says it is skipped.
find_program(GENMESH_CLANGXX NAMES clang++ clang++-16 clang++-15 clang++-14)
if(GENMESH_CLANGXX)
  add_test(NAME install.consumer_clang
    COMMAND ${CMAKE_COMMAND}
      -DGENMESH_BINARY_DIR=${PROJECT_BINARY_DIR}
      -DCONSUMER_SOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/consumer
      -DCONSUMER_EXAMPLES=${PROJECT_SOURCE_DIR}/examples
      -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/consumer_clang_work
      -DCMAKE_CXX_COMPILER=${GENMESH_CLANGXX}
      -P ${CMAKE_CURRENT_SOURCE_DIR}/consumer_test.cmake)
  set_tests_properties(install.consumer_clang PROPERTIES TIMEOUT 900)
else()
  add_test(NAME install.consumer_clang
    COMMAND sh -c "echo 'install.consumer_clang skipped: no clang++ found (scripts/run.sh test installs clang)'; exit 77")
  set_tests_properties(install.consumer_clang PROPERTIES SKIP_RETURN_CODE 77)
endif()
