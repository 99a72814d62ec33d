# Included at the end of the top-level CMakeLists.txt (cmake_language DEFER in
# codegen/CMakeLists.txt), when test_codegen and fieldcodec-gen both exist.
if(TARGET test_codegen)
  target_link_libraries(test_codegen PRIVATE fieldcodec_codegen)
endif()
