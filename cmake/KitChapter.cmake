# kit_add_chapter(NN-name): one chapter executable from chapters/NN-name/main.cpp, named
# after its folder, linked to the shared library and the selected methods. Its default
# figure folder is <build>/figures/NN-name.
function(kit_add_chapter name)
  add_executable(${name} "${CMAKE_CURRENT_SOURCE_DIR}/${name}/main.cpp")
  target_link_libraries(${name} PRIVATE kit::common kit::methods)
  # Glue that wires the selected methods to the chapters' models (spring_steppers.hpp).
  target_include_directories(${name} PRIVATE "${PROJECT_SOURCE_DIR}/chapters/shared")
  target_compile_options(${name} PRIVATE ${KIT_WARNINGS})
  target_compile_definitions(${name} PRIVATE
    KIT_CHAPTER_NAME="${name}"
    KIT_DEFAULT_FIGURE_DIR="${PROJECT_BINARY_DIR}/figures/${name}"
    KIT_CHAPTER_SOURCE_DIR="${CMAKE_CURRENT_SOURCE_DIR}/${name}")
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${PROJECT_BINARY_DIR}/bin")
endfunction()
