#pragma once

#include "interpreter/vm/bytecode.h"
#include "interpreter/vm/imagebytes.h"

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace iec::interp {

// TON, TOF and TP in C++, for op::NativeFb. They read and write the instance with the layout of
// their ST declarations in compiler/stdlib.cpp (IN, PT, Q, ET, START, RUNNING/TRIGGERED), which the
// compiler checks before it emits op::NativeFb, and behave exactly like that ST (tst_stdfb runs
// every trace both ways). Inline: the VM's handlers are the hot path of programs with many timers.

namespace nativedetail {

// The layout the compiler checks before it uses op::NativeFb: IN, PT, Q, ET, then the state
// (START and RUNNING for TON/TOF, START and TRIGGERED for TP), as declared in stdlib.cpp.
struct TimerInstance {
    std::uint8_t in;
    std::int64_t pt;
    std::uint8_t q;
    std::int64_t et;
    std::int64_t start;
    std::uint8_t flag;
};
static_assert(offsetof(TimerInstance, pt) == 8 && offsetof(TimerInstance, q) == 16 && offsetof(TimerInstance, et) == 24
              && offsetof(TimerInstance, start) == 32 && offsetof(TimerInstance, flag) == 40);

} // namespace nativedetail

inline void runNativeBlock(NativeBlock block, std::uint8_t *instance, std::int64_t now)
{
    // Field by field, each with its own size: a wide copy of the whole instance right after the
    // caller stored IN and PT would stall on store forwarding.
    nativedetail::TimerInstance t;
    t.in = instance[offsetof(nativedetail::TimerInstance, in)];
    t.pt = image::load<std::int64_t>(instance + offsetof(nativedetail::TimerInstance, pt));
    t.q = instance[offsetof(nativedetail::TimerInstance, q)];
    t.et = image::load<std::int64_t>(instance + offsetof(nativedetail::TimerInstance, et));
    t.start = image::load<std::int64_t>(instance + offsetof(nativedetail::TimerInstance, start));
    t.flag = instance[offsetof(nativedetail::TimerInstance, flag)];
    switch (block) {
    case NativeBlock::Ton:
        if (t.in) {
            if (!t.flag) {
                t.flag = 1;
                t.start = now;
            }
            if (!t.q) {
                t.et = now - t.start;
                if (t.et >= t.pt) {
                    t.et = t.pt;
                    t.q = 1;
                }
            }
        } else {
            t.flag = 0;
            t.q = 0;
            t.et = 0;
        }
        break;
    case NativeBlock::Tof:
        if (t.in) {
            t.q = 1;
            t.et = 0;
            t.flag = 0;
        } else if (t.q) {
            if (!t.flag) {
                t.flag = 1;
                t.start = now;
            }
            t.et = now - t.start;
            if (t.et >= t.pt) {
                t.et = t.pt;
                t.q = 0;
            }
        }
        break;
    case NativeBlock::Tp:
        if (t.in && !t.q && !t.flag) {
            t.q = 1;
            t.flag = 1;
            t.start = now;
        }
        if (t.q) {
            t.et = now - t.start;
            if (t.et >= t.pt) {
                t.et = t.pt;
                t.q = 0;
            }
        }
        if (!t.in && !t.q) {
            t.et = 0;
            t.flag = 0;
        }
        break;
    }
    instance[offsetof(nativedetail::TimerInstance, q)] = t.q;
    image::store<std::int64_t>(instance + offsetof(nativedetail::TimerInstance, et), t.et);
    image::store<std::int64_t>(instance + offsetof(nativedetail::TimerInstance, start), t.start);
    instance[offsetof(nativedetail::TimerInstance, flag)] = t.flag;
}

} // namespace iec::interp
