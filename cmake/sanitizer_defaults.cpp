// The sanitizer build's run-time options, linked into each of its executables
// (SKYLIT_SANITIZE), so a test, the binaries it starts and a hand run all get them;
// ASAN_OPTIONS and UBSAN_OPTIONS still override them one by one.
//
// intercept_tls_get_addr=0: GCC 12's LeakSanitizer records the dynamic TLS blocks of
// dlopen'd libraries (Mesa's) and, when a block starts 16 bytes into a page, takes its
// bounds from the 16 bytes before it (glibc 2.19's layout). Under AddressSanitizer those
// bytes are the allocator's chunk header, so its tracer scans from a small garbage
// address and dies ("Tracer caught signal 11", tests/sanitizer/dtls_exit_check.cpp):
// one 48-byte chunk in 256 starts so, and a given heap layout hits it in every run or
// never (docs/testing.md). Without the interception
// the blocks are still scanned: they are heap chunks that the thread's dtv points at.
extern "C" const char* __asan_default_options() { return "detect_leaks=1:intercept_tls_get_addr=0"; }
extern "C" const char* __ubsan_default_options() { return "print_stacktrace=1"; }
