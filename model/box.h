#pragma once

#include <memory>
#include <utility>

namespace iec::model {

// A heap-allocated value with value semantics (deep copy, compare by value). The model is a tree
// of plain values; Box breaks the recursion where a type contains itself (array of array, an
// action block with an inline body that holds action blocks, ...).
template<class T> class Box
{
public:
    Box()
        : m_value(std::make_unique<T>())
    { }
    Box(T value) // NOLINT(google-explicit-constructor): a Box is used like the value it holds
        : m_value(std::make_unique<T>(std::move(value)))
    { }
    Box(const Box &other)
        : m_value(std::make_unique<T>(*other))
    { }
    Box(Box &&other) noexcept
        : m_value(std::make_unique<T>())
    {
        m_value.swap(other.m_value); // leaves `other` holding a default value, never null
    }
    Box &operator=(const Box &other)
    {
        if (this != &other)
            *m_value = *other;
        return *this;
    }
    Box &operator=(Box &&other) noexcept
    {
        m_value.swap(other.m_value);
        return *this;
    }
    ~Box() = default;

    T &operator*() { return *m_value; }
    const T &operator*() const { return *m_value; }
    T *operator->() { return m_value.get(); }
    const T *operator->() const { return m_value.get(); }

    bool operator==(const Box &other) const { return *m_value == *other.m_value; }

private:
    std::unique_ptr<T> m_value;
};

} // namespace iec::model
