/// @file
/// The one home of the book's CPU-specific code (a header only): the vector lane types the fast
/// variants compute in, the instruction sets this build holds copies of its hot loops for, which of
/// them the host runs (asked at run time), and copy_for, which picks a loop's copy for a set. The
/// default build is portable x86-64 (SSE2) and runs the AVX2 copies where the processor has AVX2; a
/// build for another processor (the playground's WebAssembly) has the portable copies only. No
/// other file names an instruction set: the loops are written once, as templates over the set.
#pragma once

#include <array>

namespace tri::ch08 {

// [listing lane_vectors]
/// N lanes of Lane as GCC's and Clang's generic vector: each target lowers it to its own
/// instructions (SSE2 registers by default, AVX2 ones inside an AVX2 copy, scalar code where there
/// are none). A typedef: GCC ignores the attribute on a `using` alias of a dependent type.
template <class Lane, int N>
struct VectorOf {
  typedef Lane type __attribute__((vector_size(N * sizeof(Lane))));
};

template <class Lane, int N>
using Vector = typename VectorOf<Lane, N>::type;

/// The instruction sets each dispatched loop has a copy for, narrowest first.
enum class InstructionSet {
  portable,  ///< the build's own instructions: SSE2 on x86-64 (every x86-64 has it), WebAssembly's
  avx2       ///< x86-64 with AVX2: registers of 32 bytes
};

/// Every set, narrowest first: the tests force each one the host runs.
inline constexpr std::array all_instruction_sets{InstructionSet::portable, InstructionSet::avx2};

/// The bytes of one vector register in a set's copy: 16, or 32 with AVX2.
constexpr int register_bytes(InstructionSet set) noexcept {
  return set == InstructionSet::avx2 ? 32 : 16;
}

/// One register of Lane in the copy for Set.
template <class Lane, InstructionSet Set>
using Register = Vector<Lane, register_bytes(Set) / static_cast<int>(sizeof(Lane))>;
// [/listing]

// Copies of one loop: GCC and Clang compile a function with the target attribute for those
// instructions, and inline into it the loop's always-inline body.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define TUTORIAL_AVX2_COPIES 1
#else
#define TUTORIAL_AVX2_COPIES 0
#endif

/// True when the host runs the copies for `set` in this build: the portable ones always, the
/// AVX2 ones on an x86-64 processor with AVX2. Inline: a bit test of what the runtime library
/// asked the processor (cpuid) when the program loaded, cheap enough for every triangle.
inline bool host_runs(InstructionSet set) noexcept {
#if TUTORIAL_AVX2_COPIES
  if (set == InstructionSet::avx2) return __builtin_cpu_supports("avx2");
#endif
  return set == InstructionSet::portable;
}

/// The widest set the host runs: the copy every fast path takes unless its caller (a test)
/// names another.
inline InstructionSet widest_instruction_set() noexcept {
  return host_runs(InstructionSet::avx2) ? InstructionSet::avx2 : InstructionSet::portable;
}

namespace detail {

template <class Function>
struct Copies;

template <class Result, class... Args, bool NoExcept>
struct Copies<Result(Args...) noexcept(NoExcept)> {
  template <template <InstructionSet> class Loop>
  static Result portable(Args... args) {
    return Loop<InstructionSet::portable>::run(static_cast<Args>(args)...);
  }
#if TUTORIAL_AVX2_COPIES
  template <template <InstructionSet> class Loop>
  __attribute__((target("avx2"))) static Result avx2(Args... args) {
    return Loop<InstructionSet::avx2>::run(static_cast<Args>(args)...);
  }
#endif
};

}  // namespace detail

// [listing copy_for]
/// The copy of a loop compiled for `set`: Loop<Set>::run (a static function, always inlined, the
/// same parameters for every Set) inside a function compiled for Set's instructions. Where this
/// build has no copy for `set` (not x86-64), the portable one. The loop's vector code is written
/// once, with Register<Lane, Set> or register_bytes(Set) where the width matters.
template <template <InstructionSet> class Loop>
auto copy_for(InstructionSet set) noexcept {
  using Copies = detail::Copies<decltype(Loop<InstructionSet::portable>::run)>;
#if TUTORIAL_AVX2_COPIES
  if (set == InstructionSet::avx2) return &Copies::template avx2<Loop>;
#endif
  (void)set;
  return &Copies::template portable<Loop>;
}
// [/listing]

}  // namespace tri::ch08
