// SPDX-License-Identifier: GPL-3.0-or-later
// The source of the targets that make the test programs' shared precompiled header (tests/CMakeLists.txt): a target
// needs a source to compile its PCH; the header is included into this one by the compiler's -include, nothing else.
