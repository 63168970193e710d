# `k40t bag --jsonl / --csv`'s exports (tools/k40t_bag/frame_export.cpp) over the k40t tool's
# argument parsing, frame JSON and monitor lines (also the topic monitor's), ROS-free: unit-tested here, linked by the ROS build's
# k40t_ros_bag (cmake/bag.cmake), which only adds the reading of bags.
set(K40T_TOOL_SHARED_SOURCES
    ${PROJECT_SOURCE_DIR}/tools/k40t/args.cpp ${PROJECT_SOURCE_DIR}/tools/k40t/frame_text.cpp
    ${PROJECT_SOURCE_DIR}/tools/k40t/json_sink.cpp ${PROJECT_SOURCE_DIR}/tools/k40t/input.cpp
    ${PROJECT_SOURCE_DIR}/tools/k40t/frame_printer.cpp)
add_library(k40t_frame_export STATIC ${PROJECT_SOURCE_DIR}/tools/k40t_bag/frame_export.cpp
                                     ${K40T_TOOL_SHARED_SOURCES})
target_include_directories(k40t_frame_export PUBLIC ${PROJECT_SOURCE_DIR}/tools/k40t
                                                    ${PROJECT_SOURCE_DIR}/tools/k40t_bag)
target_link_libraries(k40t_frame_export PUBLIC k40t_core)
set_target_properties(k40t_frame_export PROPERTIES POSITION_INDEPENDENT_CODE ON)

# The k40t command-line tool (decode, monitor, send), ROS-free; its argument parsing and frame
# JSON are compiled once, in k40t_frame_export.
file(GLOB K40T_TOOL_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tools/k40t/*.cpp)
list(REMOVE_ITEM K40T_TOOL_SOURCES ${K40T_TOOL_SHARED_SOURCES})
if(K40T_TOOL_SOURCES)
  k40t_add_program(k40t SOURCES ${K40T_TOOL_SOURCES} LINK k40t_frame_export)
endif()

# skyport_sim: the simulated DJI SKYPORT adapter (PSDK v1), ROS-free; the control socket is
# k40t_sim's (k40t_sim_model).
file(GLOB SKYPORT_SIM_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tools/skyport_sim/*.cpp)
if(SKYPORT_SIM_SOURCES AND TARGET k40t_psdk AND TARGET k40t_sim_model)
  k40t_add_program(skyport_sim SOURCES ${SKYPORT_SIM_SOURCES} LINK k40t_psdk k40t_sim_model)
endif()
