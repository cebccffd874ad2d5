// C++ face of glsl/receiver_plane.glsl as a technique's setting: the slope
// clamp `receiver-plane=on` stands for (frame/setting_value.h reads the key).
#pragma once

namespace pn {

// `receiver-plane=on`: the receiver plane's slope clamped at 10 (84°): steeper
// receivers (walls seen edge-on from the light) keep the constant bias's share.
inline constexpr float kReceiverPlaneTan = 10.0f;

}  // namespace pn
