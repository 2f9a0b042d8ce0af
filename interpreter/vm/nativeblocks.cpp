#include "interpreter/vm/nativeblocks.h"

#include <cstddef>
#include <cstring>

namespace iec::interp {

namespace {

template<typename T>
T load(const std::uint8_t *p)
{
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

template<typename T>
void store(std::uint8_t *p, T v)
{
    std::memcpy(p, &v, sizeof v);
}

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

} // namespace

void runNativeBlock(NativeBlock block, std::uint8_t *instance, std::int64_t now)
{
    // Field by field, each with its own size: a wide copy of the whole instance right after the
    // caller stored IN and PT would stall on store forwarding.
    TimerInstance t;
    t.in = instance[offsetof(TimerInstance, in)];
    t.pt = load<std::int64_t>(instance + offsetof(TimerInstance, pt));
    t.q = instance[offsetof(TimerInstance, q)];
    t.et = load<std::int64_t>(instance + offsetof(TimerInstance, et));
    t.start = load<std::int64_t>(instance + offsetof(TimerInstance, start));
    t.flag = instance[offsetof(TimerInstance, flag)];
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
    instance[offsetof(TimerInstance, q)] = t.q;
    store<std::int64_t>(instance + offsetof(TimerInstance, et), t.et);
    store<std::int64_t>(instance + offsetof(TimerInstance, start), t.start);
    instance[offsetof(TimerInstance, flag)] = t.flag;
}

} // namespace iec::interp
