#include "chapters/08_fast_exact/instruction_sets.hpp"

namespace tri::ch08 {

bool host_runs(InstructionSet set) noexcept {
  switch (set) {
    case InstructionSet::portable:
      return true;
    case InstructionSet::avx2:
#if TUTORIAL_AVX2_COPIES
      // A bit test of what libgcc's loader-time constructor read from the processor (cpuid).
      return __builtin_cpu_supports("avx2");
#else
      return false;
#endif
  }
  return false;
}

InstructionSet widest_instruction_set() noexcept {
  return host_runs(InstructionSet::avx2) ? InstructionSet::avx2 : InstructionSet::portable;
}

}  // namespace tri::ch08
