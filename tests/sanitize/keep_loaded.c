/* Preloaded into the tests by scripts/test-sanitize.sh (not part of penumbra): dlclose
 * leaves every library mapped. Mesa's EGL unloads its DRI driver (swrast_dri.so, llvmpipe)
 * in eglTerminate, before LeakSanitizer's check at exit, and a leak report can only name a
 * library that is still mapped; with this, lsan.supp can name the driver instead of
 * "<unknown module>". Built without sanitizers: it is also loaded into sh and python3. */
int dlclose(void* handle) {
  (void)handle;
  return 0;
}
