# The ROS-free core, one library per layer, each linking only the layers below it (the includes
# follow the same order; scripts/check_layers.py checks them):
#   k40t_codec      codec/: Status/Result, byte I/O, field sinks, value checks, declarative layouts
#   k40t_transport  transport/: links by URL (needs codec/ only)
#   k40t_core       protocol/ session/ operations/: the K40T pod protocol
#   k40t_psdk       psdk/: the DJI PSDK, beside k40t_core (codec + transport, never protocol/)
# Sources are globbed per layer so each layer grows by adding files.
file(GLOB_RECURSE K40T_CODEC_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/codec/*.cpp)
add_library(k40t_codec STATIC ${K40T_CODEC_SOURCES})
target_include_directories(k40t_codec PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(k40t_codec PUBLIC Boost::headers)
set_target_properties(k40t_codec PROPERTIES POSITION_INDEPENDENT_CODE ON)

file(GLOB_RECURSE K40T_TRANSPORT_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/transport/*.cpp)
add_library(k40t_transport STATIC ${K40T_TRANSPORT_SOURCES})
target_link_libraries(k40t_transport PUBLIC k40t_codec Threads::Threads util)
set_target_properties(k40t_transport PROPERTIES POSITION_INDEPENDENT_CODE ON)

file(GLOB_RECURSE K40T_CORE_SOURCES CONFIGURE_DEPENDS
  ${PROJECT_SOURCE_DIR}/src/protocol/*.cpp
  ${PROJECT_SOURCE_DIR}/src/session/*.cpp
  ${PROJECT_SOURCE_DIR}/src/operations/*.cpp)  # ROS-free logic of the driver's actions
add_library(k40t_core STATIC ${K40T_CORE_SOURCES})
include(${CMAKE_CURRENT_LIST_DIR}/cfg_enum_names.cmake)  # the enum names of cfg/setting_enums.txt
target_include_directories(k40t_core PRIVATE ${K40T_GENERATED_INCLUDE})
target_link_libraries(k40t_core PUBLIC k40t_codec k40t_transport)
set_target_properties(k40t_core PROPERTIES POSITION_INDEPENDENT_CODE ON)

# Geodesy (src/geo/): GeographicLib for geodetic <-> ECEF <-> ENU, PROJ with proj-data's EGM96
# grid for ellipsoid <-> mean-sea-level heights. Shared by the simulators and the driver.
find_path(K40T_GEOGRAPHICLIB_INCLUDE GeographicLib/LocalCartesian.hpp REQUIRED)
find_library(K40T_GEOGRAPHICLIB_LIBRARY NAMES GeographicLib REQUIRED)
find_path(K40T_PROJ_INCLUDE proj.h REQUIRED)
find_library(K40T_PROJ_LIBRARY NAMES proj REQUIRED)
file(GLOB K40T_GEO_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/geo/*.cpp)
add_library(k40t_geo STATIC ${K40T_GEO_SOURCES})
target_include_directories(k40t_geo PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_include_directories(k40t_geo SYSTEM PRIVATE ${K40T_GEOGRAPHICLIB_INCLUDE} ${K40T_PROJ_INCLUDE})
target_link_libraries(k40t_geo PUBLIC ${K40T_GEOGRAPHICLIB_LIBRARY} ${K40T_PROJ_LIBRARY})
set_target_properties(k40t_geo PROPERTIES POSITION_INDEPENDENT_CODE ON)

file(GLOB_RECURSE K40T_PSDK_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/psdk/*.cpp)
if(K40T_PSDK_SOURCES)
  add_library(k40t_psdk STATIC ${K40T_PSDK_SOURCES})
  target_include_directories(k40t_psdk PUBLIC ${PROJECT_SOURCE_DIR}/include)
  target_link_libraries(k40t_psdk PUBLIC k40t_codec k40t_transport k40t_geo OpenSSL::Crypto)
  set_target_properties(k40t_psdk PROPERTIES POSITION_INDEPENDENT_CODE ON)
endif()

# The pod driver's ROS-free logic (src/driver/): PodDriver (link, stamps, time sync, rate dead-man,
# GPS answers), its options, the queries and jobs the glue shares, the diagnostics' levels and
# texts. ros/ wraps it in topics, services and parameters.
file(GLOB K40T_DRIVER_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/driver/*.cpp)
add_library(k40t_driver_core STATIC ${K40T_DRIVER_SOURCES})
target_include_directories(k40t_driver_core PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(k40t_driver_core PUBLIC k40t_core k40t_geo k40t_camera)
set_target_properties(k40t_driver_core PROPERTIES POSITION_INDEPENDENT_CODE ON)
