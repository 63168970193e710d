# The simulated pod: a model library (gimbal, zoom, thermal scene, laser, SD card, faults) and
# the k40t_sim executable on top of it.
file(GLOB_RECURSE K40T_SIM_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/sim/*.cpp)
if(K40T_SIM_SOURCES)
  add_library(k40t_sim_model STATIC ${K40T_SIM_SOURCES})
  target_link_libraries(k40t_sim_model PUBLIC k40t_core k40t_geo)
  set_target_properties(k40t_sim_model PROPERTIES POSITION_INDEPENDENT_CODE ON)
endif()
file(GLOB K40T_SIM_MAIN CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tools/k40t_sim/*.cpp)
if(K40T_SIM_MAIN)
  k40t_add_program(k40t_sim SOURCES ${K40T_SIM_MAIN} LINK k40t_sim_model)
endif()
