# One home for CPU-specific code (docs/DESIGN.md section 8): only chapter 08's
# instruction_sets.hpp may ask the processor what it runs or compile a function for other
# instructions. Run with -DROOT=<repository>; fails naming every other source that does. Tests
# (which force and check each copy) are exempt, as are the READMEs' listings (not sources).
cmake_minimum_required(VERSION 3.22)
set(home chapters/08_fast_exact/instruction_sets.hpp)
# The processor's features asked at run time, function multi-versioning, a function (attribute) or
# a stretch of code (pragma) compiled for other instructions.
set(forbidden "__builtin_cpu_supports|__builtin_cpu_is|target_clones|__attribute__\\(\\(target|gnu::target|#pragma GCC target|#pragma clang attribute")

set(found "")
foreach(folder common chapters measure tools fuzz tests docs)
  file(GLOB_RECURSE sources RELATIVE "${ROOT}"
       "${ROOT}/${folder}/*.cpp" "${ROOT}/${folder}/*.hpp" "${ROOT}/${folder}/*.h"
       "${ROOT}/${folder}/*.cc" "${ROOT}/${folder}/*.c")
  foreach(source IN LISTS sources)
    if(source IN_LIST home OR source MATCHES "_test\\.cpp$")
      continue()
    endif()
    file(STRINGS "${ROOT}/${source}" lines REGEX "${forbidden}")
    foreach(line IN LISTS lines)
      string(STRIP "${line}" line)
      string(APPEND found "\n  ${source}: ${line}")
    endforeach()
  endforeach()
endforeach()
if(found)
  message(FATAL_ERROR "CPU-specific code outside ${home} (choose instructions there, through "
                      "copy_for and InstructionSet):${found}")
endif()
