# kit_read_points(VAR): tests/grading/points.json, the graded exercises, read into VAR; CMake
# configures again when it changes. Read by the library (which sources the grader takes out of it
# by name) and by the tests (a judge and a student program per exercise).
function(kit_read_points var)
  set(points "${PROJECT_SOURCE_DIR}/tests/grading/points.json")
  file(READ "${points}" text)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${points}")
  set(${var} "${text}" PARENT_SCOPE)
endfunction()

# kit_points_sources(VAR POINTS): every library source an exercise may link ("sources"), once.
function(kit_points_sources var points)
  set(sources "")
  string(JSON count LENGTH "${points}" exercises)
  math(EXPR last "${count} - 1")
  foreach(i RANGE ${last})
    string(JSON listed ERROR_VARIABLE none LENGTH "${points}" exercises ${i} sources)
    if(none OR listed EQUAL 0)
      continue()
    endif()
    math(EXPR last_source "${listed} - 1")
    foreach(j RANGE ${last_source})
      string(JSON source GET "${points}" exercises ${i} sources ${j})
      list(APPEND sources "${source}")
    endforeach()
  endforeach()
  list(REMOVE_DUPLICATES sources)
  set(${var} "${sources}" PARENT_SCOPE)
endfunction()
