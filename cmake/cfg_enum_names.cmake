# cfg/setting_enums.txt -> <build>/generated/k40t_driver/protocol/cfg_enum_names.h: the names of the
# enumerated settings as C++ tables, so the protocol's to_string() of those enums (and through it
# the simulator, the SKYPORT widgets, the CLI and the JSON output) use the same list as
# cfg/K40t.cfg. A "protocol_only" line is a code the protocol knows and the cfg does not offer:
# in the table with offered = false. Generated when CMake configures; editing the list re-runs the
# configure step.
set(K40T_CFG_ENUMS ${PROJECT_SOURCE_DIR}/cfg/setting_enums.txt)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${K40T_CFG_ENUMS})
set(K40T_GENERATED_INCLUDE ${CMAKE_BINARY_DIR}/generated)

file(STRINGS ${K40T_CFG_ENUMS} k40t_enum_lines)
set(k40t_enum_text "")
set(k40t_enum_list "")
set(k40t_enum_open FALSE)
foreach(line IN LISTS k40t_enum_lines)
  string(REGEX REPLACE "#.*$" "" line "${line}")
  string(STRIP "${line}" line)
  if(line STREQUAL "")
    continue()
  endif()
  string(REPLACE "\\" "\\\\" line "${line}")
  string(REPLACE "\"" "\\\"" line "${line}")
  if(line MATCHES "^enum ([a-z_0-9]+)")
    if(k40t_enum_open)
      string(APPEND k40t_enum_text "};\n")
    endif()
    string(APPEND k40t_enum_text "inline constexpr SettingEnumName ${CMAKE_MATCH_1}[] = {\n")
    string(APPEND k40t_enum_list
           "    {\"${CMAKE_MATCH_1}\", ${CMAKE_MATCH_1}, std::size(${CMAKE_MATCH_1})},\n")
    set(k40t_enum_open TRUE)
    set(k40t_enum_name ${CMAKE_MATCH_1})
  elseif(line MATCHES
         "^(protocol_only[ \t]+)?([a-z_0-9]+)[ \t]+([0-9xXa-fA-F]+)[ \t]+([A-Za-z_0-9]+)[ \t]+(.+)$")
    if(NOT CMAKE_MATCH_2 STREQUAL k40t_enum_name)
      message(FATAL_ERROR
              "cfg/setting_enums.txt: '${line}' is not under its 'enum ${CMAKE_MATCH_2}' line")
    endif()
    if(CMAKE_MATCH_1)
      set(k40t_offered false)
    else()
      set(k40t_offered true)
    endif()
    string(APPEND k40t_enum_text
           "    {${CMAKE_MATCH_3}, \"${CMAKE_MATCH_4}\", \"${CMAKE_MATCH_5}\", ${k40t_offered}},\n")
  else()
    message(FATAL_ERROR "cfg/setting_enums.txt: cannot read the line '${line}'")
  endif()
endforeach()
if(k40t_enum_open)
  string(APPEND k40t_enum_text "};\n")
endif()
string(APPEND k40t_enum_text "inline constexpr SettingEnum all[] = {\n${k40t_enum_list}};\n")

# Written through configure_file so an unchanged list leaves the header's time stamp alone.
set(K40T_CFG_ENUM_TABLES "${k40t_enum_text}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/cfg_enum_names.h.in
               ${K40T_GENERATED_INCLUDE}/k40t_driver/protocol/cfg_enum_names.h @ONLY)
