// moved; include the new path (codec/result.h, the layer below both protocols).
#pragma once
#include "k40t_driver/codec/result.h"
