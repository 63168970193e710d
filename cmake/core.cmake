# The ROS-free core. Sources are globbed per layer so each layer grows by adding files.
file(GLOB_RECURSE K40T_CORE_SOURCES CONFIGURE_DEPENDS
  ${PROJECT_SOURCE_DIR}/src/protocol/*.cpp
  ${PROJECT_SOURCE_DIR}/src/transport/*.cpp
  ${PROJECT_SOURCE_DIR}/src/session/*.cpp
  ${PROJECT_SOURCE_DIR}/src/operations/*.cpp)  # ROS-free logic of the driver's actions
add_library(k40t_core STATIC ${K40T_CORE_SOURCES})
target_include_directories(k40t_core PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(k40t_core PUBLIC Threads::Threads util)
set_target_properties(k40t_core PROPERTIES POSITION_INDEPENDENT_CODE ON)

file(GLOB_RECURSE K40T_PSDK_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/psdk/*.cpp)
if(K40T_PSDK_SOURCES)
  find_package(OpenSSL REQUIRED)
  add_library(k40t_psdk STATIC ${K40T_PSDK_SOURCES})
  target_include_directories(k40t_psdk PUBLIC ${PROJECT_SOURCE_DIR}/include)
  target_link_libraries(k40t_psdk PUBLIC k40t_core OpenSSL::Crypto)
  set_target_properties(k40t_psdk PROPERTIES POSITION_INDEPENDENT_CODE ON)
endif()
