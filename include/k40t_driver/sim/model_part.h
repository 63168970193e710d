// One line per part of a simulator model (the pod's gimbal, the camera's SD card): the part is
// changed by the request handlers and read by the reports, so each has a mutable and a const
// accessor of the member `name_`.
#pragma once

#define K40T_MODEL_PART(Type, name) \
  Type& name() {                    \
    return name##_;                 \
  }                                 \
  const Type& name() const {        \
    return name##_;                 \
  }
