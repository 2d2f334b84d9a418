# The shipped data files found by glob, a CMake function of the core's build
# (core/CMakeLists.txt) filling core/builtin_data.h.in.

# taiwa_builtin_files(<folder> <entries var> <files var>): every *.json of
# resources/<folder>/, as the entries of a generated C++ array of
# {text, "built in: <folder>/<file>"} (core/builtin_data.h.in), and the files
# themselves. Order: the files named in resources/<folder>/listing-order.txt
# (one stem a line, # comments), then every other file alphabetically; the
# order is what the program lists them in.
function(taiwa_builtin_files folder entries_var files_var)
  set(dir ${PROJECT_SOURCE_DIR}/resources/${folder})
  file(GLOB found CONFIGURE_DEPENDS ${dir}/*.json)
  list(SORT found)
  set(ordered "")
  set(order_file ${dir}/listing-order.txt)
  if(EXISTS ${order_file})
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${order_file})
    file(STRINGS ${order_file} lines)
    foreach(line ${lines})
      string(REGEX REPLACE "#.*" "" stem "${line}")
      string(STRIP "${stem}" stem)
      if(stem STREQUAL "")
        continue()
      endif()
      if(NOT EXISTS ${dir}/${stem}.json)
        message(FATAL_ERROR "resources/${folder}/listing-order.txt names ${stem}, but there is no resources/${folder}/${stem}.json")
      endif()
      list(APPEND ordered ${dir}/${stem}.json)
    endforeach()
  endif()
  foreach(file ${found})
    if(NOT file IN_LIST ordered)
      list(APPEND ordered ${file})
    endif()
  endforeach()
  if(ordered STREQUAL "")
    message(FATAL_ERROR "no *.json in resources/${folder}/")
  endif()
  set(entries "")
  foreach(file ${ordered})
    get_filename_component(name ${file} NAME)
    file(READ ${file} text)
    string(APPEND entries "    {R\"taiwa_json(${text})taiwa_json\", \"built in: ${folder}/${name}\"},\n")
  endforeach()
  set(${entries_var} "${entries}" PARENT_SCOPE)
  set(${files_var} ${ordered} PARENT_SCOPE)
endfunction()
