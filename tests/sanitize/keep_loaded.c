/* Preloaded into the tests by scripts/test-sanitize.sh (not part of penumbra): dlclose
 * leaves every library mapped. Mesa's EGL unloads its DRI driver (swrast_dri.so, llvmpipe)
 * in eglTerminate, before LeakSanitizer's check at exit: what the driver's globals held was
 * then reported as leaked, from "<unknown module>", since a report can only name a library
 * that is still mapped. With the driver kept, its globals are scanned, and the one real leak
 * left (lsan.supp) names it. Built without sanitizers: it is also loaded into sh and python3. */
int dlclose(void* handle) {
  (void)handle;
  return 0;
}
