# ASan + UBSan for the whole build (every target), used by the sanitizer job in .ci/run.
if(PINEDA_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()
