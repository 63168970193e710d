// Every PSDK command struct (protocol document chapter 3).
#pragma once

#include "k40t_driver/psdk/commands/app_function.h"
#include "k40t_driver/psdk/commands/camera_capture.h"
#include "k40t_driver/psdk/commands/camera_lens.h"
#include "k40t_driver/psdk/commands/data_push.h"
#include "k40t_driver/psdk/commands/gimbal.h"
#include "k40t_driver/psdk/commands/osdk_function.h"
#include "k40t_driver/psdk/commands/payload_state.h"
#include "k40t_driver/psdk/commands/positioning.h"
#include "k40t_driver/psdk/commands/widgets.h"
