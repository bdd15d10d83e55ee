# Warnings are errors from day one (DEVELOPERS.md).
function(pineda_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wshadow -Wnon-virtual-dtor
    -Wcast-align -Wunused -Woverloaded-virtual -Wnull-dereference -Wimplicit-fallthrough
    -Wno-missing-field-initializers)
  if(PINEDA_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
