#!/usr/bin/python3
"""Reads the machine code of every oscillator kernel and says whether its sample loops stay vector.

Each kernel of acoustics/synthesis/oscillator_bank.cpp (accumulateAvx512, accumulateAvx2,
accumulateBaseline; one per x86-64 level, acoustics/synthesis/oscillator_kernel.h) is compiled for its own
level whatever CPU builds it, so its code can be checked on any machine, including the kernels
that machine cannot run. This disassembles the object file with objdump and, inside each
kernel's loops (the address ranges spanned by its backward branches), counts

- scalar float instructions: [v]movss, [v]addss, [v]subss, [v]mulss, [v]divss, the scalar FMAs
  (vfmadd*ss, vfmsub*ss, vfnmadd*ss, vfnmsub*ss), [v]insertps, [v]extractps, [v]cvtsi2ss:
  lane work done one float at a time (a movss of a constant from the constant pool, %rip-relative,
  is the first step of broadcasting it, not lane work, and is not counted);
- stack accesses: any operand addressed from %rsp or %rbp (a spill is a store there and a load
  back), split into stores and loads;
- the vector registers used (zmm, ymm, xmm), which show the width each kernel runs at.

It prints one line per kernel and exits 1 if any kernel has a scalar instruction or a stack
access inside a loop (0 if none), so it can be run after a compiler or code change.

usage: tools/check_kernel_code.py [OBJECT]
  OBJECT  an object file or the library archive that holds oscillator_bank.cpp's code (ctest runs
          it on build/acoustics/synthesis/libfluidsound_acoustics_synthesis.a); default
          build/acoustics/synthesis/CMakeFiles/fluidsound_acoustics_synthesis.dir/oscillator_bank.cpp.o
"""
import pathlib
import re
import subprocess
import sys

KERNELS = ("accumulateAvx512", "accumulateAvx2", "accumulateBaseline")
SCALAR = re.compile(r"^v?(mov|add|sub|mul|div)ss$|^vf(n?)m(add|sub)\d+ss$|^v?(insert|extract)ps$"
                    r"|^v?cvtsi2ssl?q?$")
CONSTANT_LOAD = re.compile(r"^-?(0x[0-9a-f]+)?\(%rip\),%xmm\d+$")
STACK = re.compile(r"\((%rsp|%rbp)[,)]")
FUNCTION = re.compile(r"^([0-9a-f]+) <(.*)>:$")
INSTRUCTION = re.compile(r"^\s+([0-9a-f]+):\s+(\S+)\s*(.*)$")
BRANCH_TARGET = re.compile(r"^([0-9a-f]+) <")


def disassemble(path):
    """{function name: [(address, mnemonic, operands)]} of every function in the object."""
    text = subprocess.run(["objdump", "-d", "--no-show-raw-insn", "-C", str(path)],
                          capture_output=True, text=True, check=True).stdout
    functions, current = {}, None
    for line in text.splitlines():
        match = FUNCTION.match(line)
        if match:
            current = functions.setdefault(match.group(2), [])
            continue
        match = INSTRUCTION.match(line)
        if match and current is not None:
            operands = match.group(3).split("#")[0].strip()  # drop objdump's address comment
            current.append((int(match.group(1), 16), match.group(2), operands))
    return functions


def loop_instructions(instructions):
    """The instructions inside any loop: between a backward branch's target and the branch."""
    ranges = []
    for address, mnemonic, operands in instructions:
        match = BRANCH_TARGET.match(operands)
        if mnemonic.startswith("j") and match and int(match.group(1), 16) <= address:
            ranges.append((int(match.group(1), 16), address))
    return [i for i in instructions if any(lo <= i[0] <= hi for lo, hi in ranges)], len(ranges)


def stack_access(operands):
    """'store', 'load' or None: AT&T syntax puts the destination last."""
    parts = re.split(r",(?![^(]*\))", operands)
    if not any(STACK.search(p) for p in parts):
        return None
    return "store" if STACK.search(parts[-1]) else "load"


def main():
    path = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else
                        "build/acoustics/synthesis/CMakeFiles/fluidsound_acoustics_synthesis.dir/oscillator_bank.cpp.o")
    functions = disassemble(path)
    clean = True
    for kernel in KERNELS:
        names = [name for name in functions if f"::{kernel}(" in name]
        if len(names) != 1:
            print(f"{kernel}: not found once in {path} ({len(names)} matches)")
            clean = False
            continue
        body, loops = loop_instructions(functions[names[0]])
        scalar = sum(1 for _, mnemonic, operands in body
                     if SCALAR.match(mnemonic) and not CONSTANT_LOAD.match(operands))
        accesses = [stack_access(operands) for _, _, operands in body]
        stores, loads = accesses.count("store"), accesses.count("load")
        widths = {reg: sum(1 for _, _, operands in body if f"%{reg}" in operands)
                  for reg in ("zmm", "ymm", "xmm")}
        print(f"{kernel:20s} {loops:3d} loops, {len(body):5d} instructions: scalar float {scalar}, "
              f"stack stores {stores}, stack loads {loads}; operands zmm {widths['zmm']}, "
              f"ymm {widths['ymm']}, xmm {widths['xmm']}")
        clean = clean and scalar == 0 and stores == 0 and loads == 0
    print("no scalar lane work and no stack access in any kernel's loops" if clean else "NOT CLEAN")
    return 0 if clean else 1


if __name__ == "__main__":
    sys.exit(main())
