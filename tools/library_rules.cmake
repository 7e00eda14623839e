# The design's rule, checked at configure time: the pure-data libraries never reach GL, EGL,
# GLFW or ImGui, however indirectly, and only the GUI reaches GLFW and ImGui. A link added
# against the rule fails the configure step with the path that breaks it.
set(HAZE_PURE_LIBRARIES haze_core haze_mesh haze_atmosphere haze_fixtures haze_scene haze_reference haze_shows haze_dmx haze_edit haze_frame
    haze_import haze_output haze_xchange)
set(HAZE_GL_ONLY PkgConfig::EGL PkgConfig::OPENGL haze_gl haze_renderer haze_shaders haze_app)
set(HAZE_GUI_ONLY glfw PkgConfig::IMGUI haze_gui)

# Every target `target` links, directly or through others, as "a -> b -> c" paths in `out`.
function(haze_link_closure target path out)
  get_target_property(links ${target} LINK_LIBRARIES)
  set(found)
  if(links)
    foreach(dep ${links})
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" dep "${dep}")
      list(APPEND found "${path} -> ${dep}")
      if(TARGET ${dep} AND NOT "${path}" MATCHES " ${dep}( |$)")
        get_target_property(kind ${dep} TYPE)
        if(NOT kind STREQUAL "INTERFACE_LIBRARY" AND NOT kind STREQUAL "UNKNOWN_LIBRARY"
           AND NOT kind STREQUAL "SHARED_LIBRARY")
          haze_link_closure(${dep} "${path} -> ${dep}" sub)
          list(APPEND found ${sub})
        endif()
      endif()
    endforeach()
  endif()
  set(${out} ${found} PARENT_SCOPE)
endfunction()

function(haze_check_forbidden target forbidden why)
  if(NOT TARGET ${target})
    return()
  endif()
  haze_link_closure(${target} ${target} paths)
  foreach(p ${paths})
    foreach(bad ${forbidden})
      if(p MATCHES "-> ${bad}$")
        message(FATAL_ERROR "library rule broken: ${p} (${why}; docs/architecture.md)")
      endif()
    endforeach()
  endforeach()
endfunction()

foreach(lib ${HAZE_PURE_LIBRARIES})
  if(NOT TARGET ${lib})
    message(FATAL_ERROR "library rule: ${lib} is listed as a pure library but not defined")
  endif()
  haze_check_forbidden(${lib} "${HAZE_GL_ONLY};${HAZE_GUI_ONLY}" "${lib} is pure data and must not reach GL or the GUI")
endforeach()
foreach(lib haze_app haze_renderer haze_gl haze_shaders)
  haze_check_forbidden(${lib} "${HAZE_GUI_ONLY}" "only the GUI links GLFW and ImGui")
endforeach()

# The layers, lowest first (docs/architecture.md, "Layers", lists the same): a library links
# only libraries of lower layers, so dependencies point one way, down. A link within a layer or
# upwards stops the configuration with the offending link.
set(HAZE_LAYERS
  "haze_core"
  "haze_mesh haze_atmosphere"
  "haze_fixtures"
  "haze_scene haze_shows"
  "haze_dmx haze_edit haze_import haze_reference haze_output haze_shaders"
  "haze_frame haze_xchange haze_gl"
  "haze_renderer"
  "haze_app"
  "haze_gui")

# The layering test (tests/cli/layering.sh) plants a wrong link, -DHAZE_PLANTED_LINK="from;to",
# to show that this check fails on it.
if(HAZE_PLANTED_LINK)
  list(GET HAZE_PLANTED_LINK 0 planted_from)
  list(GET HAZE_PLANTED_LINK 1 planted_to)
  target_link_libraries(${planted_from} PUBLIC ${planted_to})
endif()

set(layer 0)
foreach(members ${HAZE_LAYERS})
  string(REPLACE " " ";" members "${members}")
  foreach(lib ${members})
    set(haze_layer_of_${lib} ${layer})
  endforeach()
  math(EXPR layer "${layer} + 1")
endforeach()
foreach(members ${HAZE_LAYERS})
  string(REPLACE " " ";" members "${members}")
  foreach(lib ${members})
    if(NOT TARGET ${lib})
      continue()  # not built in this configuration (no GL, no GUI)
    endif()
    get_target_property(links ${lib} LINK_LIBRARIES)
    if(NOT links)
      continue()
    endif()
    foreach(dep ${links})
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" dep "${dep}")
      if(NOT dep MATCHES "^haze_")
        continue()
      endif()
      if(NOT DEFINED haze_layer_of_${dep})
        message(FATAL_ERROR "library rule: ${dep} (linked by ${lib}) is in no layer of HAZE_LAYERS")
      endif()
      if(NOT haze_layer_of_${dep} LESS haze_layer_of_${lib})
        message(FATAL_ERROR "library rule broken: ${lib} -> ${dep} (a link must point to a lower layer; "
                            "docs/architecture.md, \"Layers\")")
      endif()
    endforeach()
  endforeach()
endforeach()
foreach(lib ${HAZE_PURE_LIBRARIES})
  if(NOT DEFINED haze_layer_of_${lib})
    message(FATAL_ERROR "library rule: ${lib} is in no layer of HAZE_LAYERS")
  endif()
endforeach()

# The folders show the same order: a library's folder (the first part of its path) is one of
# HAZE_FOLDERS, and it links only libraries of its own folder or of folders listed before it, so
# a reader can tell the direction of every dependency from the tree alone.
set(HAZE_FOLDERS fixtures atmosphere shows shaders renderer app)
# The index in HAZE_FOLDERS of the top-level folder `lib` is defined in, into `out`.
function(haze_folder_index lib out)
  get_target_property(dir ${lib} SOURCE_DIR)
  file(RELATIVE_PATH rel ${HAZE_ROOT} ${dir})
  string(REGEX REPLACE "/.*" "" top "${rel}")
  list(FIND HAZE_FOLDERS "${top}" index)
  if(index LESS 0)
    message(FATAL_ERROR "library rule: ${lib} lives in ${rel}/, which is in no folder of HAZE_FOLDERS")
  endif()
  set(${out} ${index} PARENT_SCOPE)
endfunction()
foreach(members ${HAZE_LAYERS})
  string(REPLACE " " ";" members "${members}")
  foreach(lib ${members})
    if(NOT TARGET ${lib})
      continue()
    endif()
    haze_folder_index(${lib} from_index)
    get_target_property(links ${lib} LINK_LIBRARIES)
    foreach(dep ${links})
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" dep "${dep}")
      if(NOT dep MATCHES "^haze_" OR NOT TARGET ${dep})
        continue()
      endif()
      haze_folder_index(${dep} to_index)
      if(to_index GREATER from_index)
        list(GET HAZE_FOLDERS ${from_index} from_folder)
        list(GET HAZE_FOLDERS ${to_index} to_folder)
        message(FATAL_ERROR "library rule broken: ${lib} -> ${dep} (${from_folder}/ must not link "
                            "${to_folder}/, which comes later in HAZE_FOLDERS; docs/architecture.md, \"Layers\")")
      endif()
    endforeach()
  endforeach()
endforeach()
