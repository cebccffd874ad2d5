// light.glsl — PnLight (light_model.glsl's struct) from the frame block.
PnLight exPnLight() {
  return PnLight(exLight0.x, exLight0.y, exLight0.z, exLight0.w, exLight1.x, exLight1.y);
}
