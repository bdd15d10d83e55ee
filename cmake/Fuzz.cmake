# libFuzzer build (tests/fuzz, scripts/fuzz.sh): clang only. Every target gets coverage
# instrumentation plus ASan and UBSan so that the fuzzer sees Pineda's branches and any memory
# or arithmetic error aborts the run; only the fuzzer executable links libFuzzer's main.
if(PINEDA_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "PINEDA_FUZZ needs clang (configure with CXX=clang++ CC=clang)")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
    -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()
