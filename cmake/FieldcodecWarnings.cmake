# Warning flags of the project's own targets (not exported to users): warnings are errors.
add_library(fieldcodec_warnings INTERFACE)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(fieldcodec_warnings INTERFACE
    -Wall -Wextra -Wpedantic -Werror -Wconversion -Wsign-conversion -Wshadow)
endif()
