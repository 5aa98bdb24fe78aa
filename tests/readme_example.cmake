# cmake -P script: the README's example must be examples/quick_start.cpp verbatim.
file(READ ${SOURCE_DIR}/README.md readme)
file(READ ${SOURCE_DIR}/examples/quick_start.cpp example)
# The README shows the file without its first (comment) line.
string(REGEX REPLACE "^[^\n]*\n" "" example_body "${example}")
string(FIND "${readme}" "${example_body}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "README.md's example differs from examples/quick_start.cpp")
endif()
