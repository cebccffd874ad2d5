// After the modules: values of their types, where the snippet's modules define them.
#ifdef PENUMBRA_LIGHT_MODEL_GLSL
const PnLight light = PnLight(2.0, 1.0, 2.0, 512.0, 0.0, 0.0);
#endif
#ifdef PENUMBRA_SAVSM_GLSL
const PnSavsmSettings settings = PnSavsmSettings(0.02, 1.0, 1e-4, 0.2, PN_SAVSM_BLOCKER_MIN, true);
#endif
// Any call's visibility in cascade i (cascades.md's snippet).
float visibilityIn(int i) { return float(i) * 0.1; }
