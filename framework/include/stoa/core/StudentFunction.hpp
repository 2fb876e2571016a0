#pragma once
// One function a student writes that the framework calls. The framework holds
// it as an entry of the student-code table (StudentCode.hpp) and calls it like
// a function; the lab program fills the entry at start-up with the student's
// function (or a test fills it with a double). An entry nobody filled throws
// NotImplemented with the function's name, as a stub does:
//
//   StudentFunction<float(float)> half{"half()"};
//   half = [](float x) { return x / 2; };     // handed over
//   float y = half(3.0f);                      // 1.5; unset: throws NotImplemented("half()")

#include <stoa/core/NotImplemented.hpp>

#include <functional>
#include <type_traits>
#include <utility>

namespace stoa {

template <class Signature>
class StudentFunction;

template <class Result, class... Args>
class StudentFunction<Result(Args...)> {
public:
    using Function = std::function<Result(Args...)>;

    /// `name`: the function as the student's header declares it, e.g. "lookAtMatrix()".
    explicit StudentFunction(const char* name) : m_name(name) {}

    /// Hands the function over (a function, a lambda, or nullptr to unset it).
    /// Not for another StudentFunction (that is a copy): the test comes first,
    /// so that copying a table whose types are only declared never asks whether
    /// a StudentFunction converts to a std::function (clang would need the
    /// complete result type for it).
    template <class F, class = std::enable_if_t<std::conjunction_v<
                           std::negation<std::is_same<std::decay_t<F>, StudentFunction>>, std::is_constructible<Function, F>>>>
    StudentFunction& operator=(F&& function) {
        m_function = std::forward<F>(function);
        return *this;
    }

    /// Whether a function was handed over; a pass that is optional asks this first.
    explicit operator bool() const { return static_cast<bool>(m_function); }
    const char* name() const { return m_name; }

    /// The plain function handed over, if it was one of type F (a function
    /// pointer), else null: for a hot loop that calls it millions of times a
    /// second without std::function's indirection (it calls operator() when null).
    template <class F>
    const F* target() const {
        return m_function.template target<F>();
    }

    /// Calls the function; unset, throws NotImplemented naming it.
    Result operator()(Args... args) const {
        if (!m_function) throw NotImplemented(m_name, "");
        return m_function(std::forward<Args>(args)...);
    }

private:
    const char* m_name;
    Function m_function;
};

} // namespace stoa
