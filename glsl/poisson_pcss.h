// poisson_pcss.h — the constants that glsl/poisson_pcss.glsl and the C++
// runner share (runner/pipeline: the disk's uniform buffer and the settings'
// limits). Valid as GLSL and as C++: only comments and guarded #defines.
// An engine may define them before including poisson_pcss.glsl.

#ifndef PENUMBRA_POISSON_PCSS_H
#define PENUMBRA_POISSON_PCSS_H

// Size of the disk parameter array (vec2 points[PN_POISSON_MAX_SAMPLES]) and
// the largest runtime sample count it takes.
#ifndef PN_POISSON_MAX_SAMPLES
#define PN_POISSON_MAX_SAMPLES 64
#endif

// Default sample counts of Poisson PCSS (seeds 002 / 004): blocker search, PCF.
#ifndef PN_POISSON_BLOCKER_SAMPLES
#define PN_POISSON_BLOCKER_SAMPLES 36
#endif
#ifndef PN_POISSON_PCF_SAMPLES
#define PN_POISSON_PCF_SAMPLES 64
#endif

#endif  // PENUMBRA_POISSON_PCSS_H
