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
