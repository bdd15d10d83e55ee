# ASan + UBSan for the whole build (every target), used by the sanitizer job in .ci/run.
if(PINEDA_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()

# ThreadSanitizer (scripts/tsan.sh). Cannot be combined with ASan.
if(PINEDA_TSAN)
  if(PINEDA_SANITIZE)
    message(FATAL_ERROR "PINEDA_TSAN and PINEDA_SANITIZE cannot be combined")
  endif()
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
endif()
