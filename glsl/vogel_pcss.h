// vogel_pcss.h — the constants that glsl/vogel_pcss.glsl and the C++ runner
// share (the settings' limits, the defaults). Valid as GLSL and as C++: only
// comments and guarded #defines. An engine may define them before the include.

#ifndef PENUMBRA_VOGEL_PCSS_H
#define PENUMBRA_VOGEL_PCSS_H

// The largest sample count a disk takes (the loops' bound).
#ifndef PN_VOGEL_MAX_SAMPLES
#define PN_VOGEL_MAX_SAMPLES 128
#endif

// Default sample counts of the call: blocker search, PCF (engines ship 12–32).
#ifndef PN_VOGEL_BLOCKER_SAMPLES
#define PN_VOGEL_BLOCKER_SAMPLES 16
#endif
#ifndef PN_VOGEL_PCF_SAMPLES
#define PN_VOGEL_PCF_SAMPLES 32
#endif

// The golden angle in turns, (3 - sqrt 5) / 2: sample k turns k times this.
#define PN_VOGEL_GOLDEN_TURN 0.3819660112501051

// Interleaved gradient noise (Jimenez 2014): fract(z · fract(dot(pixel, xy))).
#define PN_IGN_X 0.06711056
#define PN_IGN_Y 0.00583715
#define PN_IGN_Z 52.9829189

#endif  // PENUMBRA_VOGEL_PCSS_H
