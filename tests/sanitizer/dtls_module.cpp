// A library with dynamic TLS: dlopen'd, its thread_local block is malloc'd by glibc at the
// first access from each thread (tests/sanitizer/dtls_exit_check.cpp).
thread_local long block[4];

extern "C" long* dtls_block() { return block; }
