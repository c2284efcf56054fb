# Makes CGAL's demo meshes (Debian package libcgal-demo, file data.tar.gz)
# available to the examples: the meshes they use by default are extracted into
# the build tree, and CGAL_DATA_DIR points there so that
# CGAL::data_file_path("meshes/x.off") finds them, as in CGAL's own examples.
# Must run before find_package(CGAL), which reads CGAL_DATA_DIR.
set(SMDF_CGAL_DEMO_DATA "/usr/share/doc/libcgal-dev/data.tar.gz" CACHE FILEPATH
    "CGAL's demo data archive (Debian package libcgal-demo)")
set(SMDF_DEFAULT_MESHES meshes/fandisk.off)
set(SMDF_DATA_ROOT "${CMAKE_BINARY_DIR}/cgal-data")

if(NOT CGAL_DATA_DIR)
  if(EXISTS "${SMDF_CGAL_DEMO_DATA}")
    set(_missing FALSE)
    foreach(m ${SMDF_DEFAULT_MESHES})
      if(NOT EXISTS "${SMDF_DATA_ROOT}/data/${m}")
        set(_missing TRUE)
      endif()
    endforeach()
    if(_missing)
      set(_members "")
      foreach(m ${SMDF_DEFAULT_MESHES})
        list(APPEND _members "data/${m}")
      endforeach()
      file(MAKE_DIRECTORY "${SMDF_DATA_ROOT}")
      execute_process(COMMAND tar xzf "${SMDF_CGAL_DEMO_DATA}" ${_members}
                      WORKING_DIRECTORY "${SMDF_DATA_ROOT}" RESULT_VARIABLE _rc)
      if(NOT _rc EQUAL 0)
        message(WARNING "Could not extract the default meshes from ${SMDF_CGAL_DEMO_DATA}")
      endif()
    endif()
    set(CGAL_DATA_DIR "${SMDF_DATA_ROOT}/data")
  else()
    message(STATUS "NOTICE: ${SMDF_CGAL_DEMO_DATA} not found (Debian package libcgal-demo): "
                   "the examples will need a mesh on their command line.")
    set(CGAL_DATA_DIR "${SMDF_DATA_ROOT}/data")
  endif()
endif()
