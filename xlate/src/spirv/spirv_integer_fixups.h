// D3D10+'s integer instructions on the SPIR-V glslang emits, where SPIR-V (and GLSL after it)
// leaves the result undefined and D3D defines it. Each runs on the unoptimised module with the
// other fix-ups (spirv_fixups.h), or between legalisation passes where spirv-opt's folding would
// meet it. Each is a pass of parsed_spirv.h: true when it changed the module.
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// D3D's ishl/ishr/ushr use the low 5 bits of the shift count (`1 << 33` is 2, `x >> -1` is
// x >> 31); SPIR-V's shifts are undefined from 32 on (llvmpipe gives 0). Masks every count with 31.
bool maskShiftCounts(ParsedSpirv& m);

// D3D's ftou saturates: a negative float (and NaN) converts to 0; SPIR-V's OpConvertFToU (GLSL's
// uint()) is undefined there (llvmpipe wraps -3.6 to 4294967293). Clamps the operand at 0 first.
bool floatToUnsignedSaturates(ParsedSpirv& m);

// INT_MIN / -1 and INT_MIN % -1 of constant operands: spirv-opt's folder computes them in C++,
// which traps (SIGFPE) on x86. Folds them first as D3D computes them (the quotient wraps to
// INT_MIN, the remainder is 0), for legalizeSpirv to call before each folding pass.
bool foldIntMinByMinusOne(ParsedSpirv& m);

// SM2-3 have no integers: fxc computes int and uint values as floats, so `/` and `%` of
// non-constant operands divide floats and truncate (16777217 % 10 is 6: 16777217 is 16777216 as a
// float). Rewrites OpSDiv/OpUDiv/OpSRem/OpUMod into that: convert both operands to float, OpFDiv
// or OpFRem (truncating), convert back. fxc folds constant operands exactly (16777217 % 10 is 7
// there), so for SM2-3 modules this runs after legalisation has folded the constant ones.
bool integerDivisionInFloats(ParsedSpirv& m);

// SM2-3: fxc negates an int as a float, constants too (`-a` of 16782201 is -16782200; vkd3d's
// arithmetic-int pins it): OpSNegate becomes convert to float, OpFNegate, convert back. Before
// legalisation, so that folding sees the float negation.
bool integerNegationInFloats(ParsedSpirv& m);

// SM2-3: an int holds any float's integer value, so INT_MIN / -1 of constants is 2^31 (vkd3d's
// arithmetic-int; D3D10's idiv wraps it to INT_MIN, foldIntMinByMinusOne): the division is done
// in floats, for integerCastsOfFloatIntegers to carry the quotient to a float reader.
bool intMinByMinusOneInFloats(ParsedSpirv& m);

// SM2-3: int and uint are floats, so converting one to float changes nothing that SPIR-V's 32-bit
// integers would wrap: float(int(f)) is trunc(f) (2^31 from -INT_MIN stays 2^31), float((int)u)
// of a uint is float(u) (0xfffffffe stays 4294967294; vkd3d's cast-to-int). A float conversion of
// an int vector built from scalars converts each scalar, so that these rules meet them. Runs
// before each folding of legalisation, so that constants fold through the floats.
bool integerCastsOfFloatIntegers(ParsedSpirv& m);

}  // namespace fxport::xlate
