#!/usr/bin/env python3
"""symcr-c++ / symcr-cc: symcr as a compiler wrapper, for any build system.

    CXX="symcr-c++ g++"  CC="symcr-cc gcc"

A compile command (-c, one C or C++ source) runs symcr-gen over that one source (its unit),
compiles the generated wrapper instead of the source with the same flags, and puts the unit's
part of the program's schema into the object file, in a section of its own (.symcr_part, not
loaded), so that it travels wherever the object goes, static archives included. A source whose
unit holds no root and no program point is compiled by the original command, untouched.

A link command gathers the parts of the objects and static archives it links, has symcr-gen
merge them (a type described differently in two units is an error naming both sources),
compiles the program's schema and links the symcr runtime. A link without parts is untouched.

Options, taken off the command line before the compiler sees it, or from the environment:
  --symcr-annotations=<file>  SYMCR_ANNOTATIONS   the sidecar annotation file(s) (':' between
                                                  files in the variable); by default the first
                                                  file named .symcr found upward from the
                                                  source's directory, as .clang-format is found
  --symcr-program=<name>      SYMCR_PROGRAM       the program's name in its checkpoints
  SYMCR_WRAPPER_LOG=<file>    appends "generate <source>" and "link <output>" per run
"""
import hashlib
import json
import os
import re
import shlex
import struct
import subprocess
import sys
import tempfile

# Filled in when the wrapper is installed or built (wrapper/CMakeLists.txt): paths relative to
# this script's directory, or absolute.
CONFIG = {
    "gen": "@SYMCR_WRAPPER_GEN@",
    "include": "@SYMCR_WRAPPER_INCLUDE@",
    "runtime": "@SYMCR_WRAPPER_RUNTIME@",
    "device": "@SYMCR_WRAPPER_DEVICE@",
}

SOURCE_EXTENSIONS = {".c", ".cc", ".cpp", ".cxx", ".c++", ".C", ".cp", ".CPP"}
PART_SECTION = ".symcr_part"
SIDECAR_NAME = ".symcr"


def fail(message):
    sys.stderr.write("symcr-wrapper: error: " + message + "\n")
    sys.exit(1)


def configured(key):
    value = CONFIG[key]
    if value.startswith("@SYMCR"):
        fail("this copy of the wrapper was not configured (build or install symcr)")
    if not os.path.isabs(value):
        value = os.path.normpath(os.path.join(os.path.dirname(os.path.realpath(__file__)), value))
    return value


def log(line):
    path = os.environ.get("SYMCR_WRAPPER_LOG")
    if path:
        with open(path, "a") as out:
            out.write(line + "\n")


def run(command):
    return subprocess.call(command)


# Flags that take their value as the next argument (so that value is not taken for a source).
ARG_FLAGS = {"-o", "-MF", "-MT", "-MQ", "-x", "-I", "-D", "-U", "-include", "-imacros",
             "-isystem", "-iquote", "-idirafter", "-isysroot", "-L", "-l", "-Xlinker",
             "-Xassembler", "-Xpreprocessor", "-T", "-e", "-u", "-z", "--param", "-arch",
             "-target", "-MJ"}


class Command:
    """The compiler's arguments, with the symcr options taken off."""

    def __init__(self, args):
        self.annotations = []
        self.program = os.environ.get("SYMCR_PROGRAM", "")
        self.args = []
        for arg in args:
            if arg.startswith("--symcr-annotations="):
                self.annotations.append(os.path.abspath(arg.split("=", 1)[1]))
            elif arg.startswith("--symcr-program="):
                self.program = arg.split("=", 1)[1]
            else:
                self.args.append(arg)
        if not self.annotations and os.environ.get("SYMCR_ANNOTATIONS"):
            self.annotations = [os.path.abspath(f)
                                for f in os.environ["SYMCR_ANNOTATIONS"].split(":") if f]

    def positional(self):
        """(index, argument) of every input that is not a flag's value."""
        skip = False
        for index, arg in enumerate(self.args):
            if skip:
                skip = False
                continue
            if arg in ARG_FLAGS:
                skip = True
                continue
            if arg.startswith("-"):
                continue
            yield index, arg

    def has(self, *flags):
        return any(arg in flags for arg in self.args)

    def output(self):
        for index, arg in enumerate(self.args):
            if arg == "-o" and index + 1 < len(self.args):
                return self.args[index + 1]
            if arg.startswith("-o") and len(arg) > 2:
                return arg[2:]
        return None


def find_sidecar(source):
    directory = os.path.dirname(os.path.abspath(source))
    while True:
        candidate = os.path.join(directory, SIDECAR_NAME)
        if os.path.isfile(candidate):
            return candidate
        parent = os.path.dirname(directory)
        if parent == directory:
            return None
        directory = parent


def depfile_of(command, obj):
    args = command.args
    for index, arg in enumerate(args):
        if arg == "-MF" and index + 1 < len(args):
            return args[index + 1]
        if arg.startswith("-MF") and len(arg) > 3:
            return arg[3:]
    if command.has("-MD", "-MMD"):
        return os.path.splitext(obj)[0] + ".d"
    return None


def compile_unit(compiler, command, index, source):
    obj = command.output() or os.path.splitext(os.path.basename(source))[0] + ".o"
    annotations = command.annotations
    if not annotations:
        sidecar = find_sidecar(source)
        annotations = [sidecar] if sidecar else []
    unit_dir = os.path.abspath(obj) + ".symcr"
    os.makedirs(unit_dir, exist_ok=True)
    for stale in os.listdir(unit_dir):
        if stale.startswith("tu0_"):
            os.remove(os.path.join(unit_dir, stale))
    # symcr-gen reads the source's own command (the compiler asked for its defaults, a cross
    # compiler followed) from a one-entry compilation database.
    database = [{"directory": os.getcwd(), "file": os.path.abspath(source),
                 "arguments": [compiler] + command.args}]
    with open(os.path.join(unit_dir, "compile_commands.json"), "w") as out:
        json.dump(database, out)
    unit = "u" + hashlib.sha1(os.path.abspath(obj).encode()).hexdigest()[:12]
    part = os.path.join(unit_dir, "part.json")
    gen = [configured("gen"), "-p", unit_dir, "--unit", unit, "--part-file", part,
           "--out-dir", unit_dir, "-j", "1"]
    for file in annotations:
        gen += ["--annotations", file]
    if command.program:
        gen += ["--program", command.program]
    gen.append(os.path.abspath(source))
    log("generate " + os.path.abspath(source))
    status = run(gen)
    if status != 0:
        return status
    with open(part) as f:
        model = json.load(f)
    name = os.path.basename(source)
    pointed = os.path.exists(os.path.join(unit_dir, "tu0_points_" + name))
    if not model["roots"] and not pointed:
        status = run([compiler] + command.args)  # nothing of symcr's: the original command
        return status if status != 0 else add_to_depfile(command, obj, annotations)
    wrapper = os.path.join(unit_dir, "tu0_" + name)
    unit_source = os.path.join(unit_dir, "unit" + os.path.splitext(name)[1])
    # .incbin: the assembler copies the part into the object, with no flags: never loaded.
    with open(unit_source, "w") as out:
        out.write('#include "%s"\n__asm__(".pushsection %s,\\"\\",%%progbits\\n'
                  '.incbin \\"%s\\"\\n.popsection");\n' % (wrapper, PART_SECTION, part))
    args = list(command.args)
    args[index] = unit_source
    # The generated code includes symcr's headers: found after the project's own directories.
    args += ["-Wno-unknown-pragmas", "-idirafter", configured("include")]
    status = run([compiler] + args)
    return status if status != 0 else add_to_depfile(command, obj, annotations)


def add_to_depfile(command, obj, annotations):
    """The sidecar is read by symcr-gen, not the compiler: editing it must recompile the source
    (whether its unit had anything of symcr's or not: the edit may add a root to it)."""
    depfile = depfile_of(command, obj)
    if depfile and os.path.exists(depfile) and annotations:
        with open(depfile) as f:
            text = f.read()
        extra = " ".join(a.replace(" ", "\\ ") for a in annotations)
        text = re.sub(r":(\s)", ": " + extra + r" \\\n \1", text, count=1)
        with open(depfile, "w") as out:
            out.write(text)
    return 0


# --- reading the parts back: ELF objects, in static archives or not ------------------------

def elf_section(data, name):
    if data[:4] != b"\x7fELF":
        return None
    is64 = data[4] == 2
    endian = "<" if data[5] == 1 else ">"
    if is64:
        shoff, = struct.unpack_from(endian + "Q", data, 0x28)
        shentsize, shnum, shstrndx = struct.unpack_from(endian + "HHH", data, 0x3A)
    else:
        shoff, = struct.unpack_from(endian + "I", data, 0x20)
        shentsize, shnum, shstrndx = struct.unpack_from(endian + "HHH", data, 0x2E)

    def header(i):
        base = shoff + i * shentsize
        if is64:
            nameoff, _, _, _, offset, size = struct.unpack_from(endian + "IIQQQQ", data, base)
        else:
            nameoff, _, _, _, offset, size = struct.unpack_from(endian + "IIIIII", data, base)
        return nameoff, offset, size

    _, stroff, strsize = header(shstrndx)
    strings = data[stroff:stroff + strsize]
    for i in range(shnum):
        nameoff, offset, size = header(i)
        end = strings.find(b"\0", nameoff)
        if strings[nameoff:end].decode(errors="replace") == name:
            return data[offset:offset + size]
    return None


def archive_members(path, data):
    """(name, bytes) of each member of a System V / GNU ar archive. A thin archive (ar T, as
    Meson makes them) names its members' files, relative to the archive, instead of holding them."""
    thin = data.startswith(b"!<thin>\n")
    pos = 8
    names = b""
    while pos + 60 <= len(data):
        header = data[pos:pos + 60]
        name = header[:16].decode(errors="replace").rstrip()
        size = int(header[48:58].decode().strip())
        special = name in ("/", "//", "/SYM64/")
        stored = size if special or not thin else 0
        body = data[pos + 60:pos + 60 + stored]
        pos += 60 + stored + (stored & 1)
        if name == "//":
            names = body
            continue
        if special:
            continue
        long_name = re.match(r"^/(\d+)", name)  # GNU: an offset into the "//" member
        if long_name:
            start = int(long_name.group(1))
            name = names[start:names.find(b"/\n", start)].decode(errors="replace")
        name = name.rstrip("/")
        if thin:
            with open(os.path.join(os.path.dirname(path), name), "rb") as member:
                body = member.read()
        yield name, body


def split_parts(origin, section):
    """A part is one line of JSON; a relocatable link (ld -r) concatenates its objects' parts."""
    for line in section.split(b"\n"):
        if line.strip(b"\0 \t\r"):
            yield origin, line.strip(b"\0 \t\r")


def parts_of(path):
    with open(path, "rb") as f:
        data = f.read()
    if data.startswith((b"!<arch>\n", b"!<thin>\n")):
        for member, body in archive_members(path, data):
            section = elf_section(body, PART_SECTION)
            if section:
                yield from split_parts("%s(%s)" % (path, member), section)
    else:
        section = elf_section(data, PART_SECTION)
        if section:
            yield from split_parts(path, section)


def expanded(args):
    """The arguments with response files (@file, as Meson and Ninja write long commands) read."""
    result = []
    for arg in args:
        if arg.startswith("@") and os.path.isfile(arg[1:]):
            with open(arg[1:]) as f:
                result.extend(expanded(shlex.split(f.read())))
        else:
            result.append(arg)
    return result


def link_inputs(command):
    search = []
    args = expanded(command.args)
    command = Command(args)
    for index, arg in enumerate(args):
        if arg == "-L" and index + 1 < len(args):
            search.append(args[index + 1])
        elif arg.startswith("-L") and len(arg) > 2:
            search.append(arg[2:])
    inputs = []
    for index, arg in enumerate(args):
        library = None
        if arg == "-l" and index + 1 < len(args):
            library = args[index + 1]
        elif arg.startswith("-l") and len(arg) > 2:
            library = arg[2:]
        if library is not None:
            # The linker prefers a shared library, which carries no parts.
            for directory in search:
                if os.path.exists(os.path.join(directory, "lib%s.so" % library)):
                    break
                archive = os.path.join(directory, "lib%s.a" % library)
                if os.path.exists(archive):
                    inputs.append(archive)
                    break
    for _, arg in command.positional():
        if os.path.isfile(arg) and not arg.endswith((".so", ".ld", ".lds")):
            inputs.append(arg)
    return inputs


# Link flags that select the target or code model: the schema is compiled with them too.
TARGET_FLAG = re.compile(r"^(-m.*|--target=.*|-target|--sysroot=.*|-march=.*|-mcpu=.*|"
                         r"-f(no-)?(pic|PIC|pie|PIE)|-fsanitize=.*|-flto.*|-isysroot)$")


def cxx_for(compiler):
    """The C++ driver beside a C compiler (gcc -> g++, clang -> clang++, x-gcc-12 -> x-g++-12)."""
    head, base = os.path.split(compiler)
    for c, cxx in (("clang", "clang++"), ("gcc", "g++"), ("cc", "c++")):
        match = re.search(r"(^|-)%s(-[0-9.]+)?$" % re.escape(c), base)
        if match:
            return os.path.join(head, base[:match.start()] + match.group(1) + cxx +
                                (match.group(2) or ""))
    return compiler


def link(compiler, command, is_c):
    parts = []
    for path in link_inputs(command):
        parts.extend(parts_of(path))
    if not parts:
        return run([compiler] + command.args)
    output = command.output() or "a.out"
    log("link " + os.path.abspath(output))
    out_dir = os.path.abspath(output) + ".symcr"
    os.makedirs(out_dir, exist_ok=True)
    gen = [configured("gen"), "--out-dir", out_dir,
           "--schema-file", os.path.abspath(output) + ".symcr-schema"]
    if command.program:
        gen += ["--program", command.program]
    with tempfile.TemporaryDirectory(prefix="symcr-link-") as temp:
        for number, (origin, part) in enumerate(parts):
            path = os.path.join(temp, "%d.json" % number)
            with open(path, "wb") as out:
                out.write(part)
            gen += ["--link-part", path]
        status = run(gen + ["--"])
    if status != 0:
        sys.stderr.write("symcr-wrapper: the parts came from: %s\n"
                         % ", ".join(origin for origin, _ in parts))
        return status
    cxx = cxx_for(compiler) if is_c else compiler
    schema_object = os.path.join(out_dir, "symcr_schema.o")
    target_flags = []
    args = command.args
    for index, arg in enumerate(args):
        if TARGET_FLAG.match(arg):
            target_flags.append(arg)
            if arg in ("-target", "-isysroot") and index + 1 < len(args):
                target_flags.append(args[index + 1])
    status = run([cxx, "-c", "-O2", "-I" + configured("include")] + target_flags +
                 [os.path.join(out_dir, "symcr_schema.cpp"), "-o", schema_object])
    if status != 0:
        return status
    extra = [schema_object, configured("runtime"), configured("device")]
    if is_c:
        extra += ["-lstdc++", "-lm"]
    return run([compiler] + command.args + extra)


def main(argv):
    tool = os.path.basename(argv[0])
    if len(argv) < 2:
        sys.stderr.write("usage: %s <compiler> <compiler arguments>...\n" % tool)
        return 2
    compiler = argv[1]
    command = Command(argv[2:])
    is_c = tool.endswith("-cc")
    if command.has("-E", "-M", "-MM", "-S", "--version", "-v", "-dumpversion",
                   "-dumpmachine", "-print-search-dirs") or not command.args:
        return run([compiler] + command.args)
    sources = [(index, arg) for index, arg in command.positional()
               if os.path.splitext(arg)[1] in SOURCE_EXTENSIONS]
    if command.has("-c"):
        if len(sources) != 1:
            # Not one unit per command: compiled as written (no checkpoint code for these).
            if sources:
                sys.stderr.write("symcr-wrapper: warning: %d sources in one compile command "
                                 "are compiled without symcr\n" % len(sources))
            return run([compiler] + command.args)
        return compile_unit(compiler, command, *sources[0])
    if command.has("-shared", "-r", "-Wl,-r", "--relocatable"):
        # A shared library's or a relocatable object's parts stay in it: the program's link reads
        # a relocatable object's; a shared library holds no roots symcr can serve.
        return run([compiler] + command.args)
    if sources:
        sys.stderr.write("symcr-wrapper: warning: compiling and linking in one command "
                         "bypasses symcr: compile with -c, then link\n")
        return run([compiler] + command.args)
    return link(compiler, command, is_c)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
