# kit_chapter_settings(TARGET NN-name): what chapters/NN-name/main.cpp needs to compile and link
# in TARGET: the shared library, the lessons, the selected methods and the chapter's names. Its
# main.cpp finds its own lesson headers beside it, and kit::lessons gives chapters/shared.
# Its default figure folder is <build>/figures/NN-name.
function(kit_chapter_settings target name)
  target_link_libraries(${target} PRIVATE kit::lessons kit::common kit::methods)
  target_compile_definitions(${target} PRIVATE
    KIT_CHAPTER_NAME="${name}"
    KIT_DEFAULT_FIGURE_DIR="${PROJECT_BINARY_DIR}/figures/${name}"
    KIT_CHAPTER_SOURCE_DIR="${PROJECT_SOURCE_DIR}/chapters/${name}")
endfunction()

# kit_add_chapter(NN-name): one chapter executable from chapters/NN-name/main.cpp, named after
# its folder, in <build>/bin.
function(kit_add_chapter name)
  add_executable(${name} "${PROJECT_SOURCE_DIR}/chapters/${name}/main.cpp")
  kit_chapter_settings(${name} ${name})
  target_compile_options(${name} PRIVATE ${KIT_WARNINGS})
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${PROJECT_BINARY_DIR}/bin")
endfunction()

# kit_use_lessons(TARGET NN-name...): TARGET (a test or a benchmark) links the lessons and includes
# the named chapters' own headers, as their main.cpp does from beside them.
function(kit_use_lessons target)
  target_link_libraries(${target} PRIVATE kit::lessons)
  foreach(chapter IN LISTS ARGN)
    target_include_directories(${target} PRIVATE "${PROJECT_SOURCE_DIR}/chapters/${chapter}")
  endforeach()
endfunction()
