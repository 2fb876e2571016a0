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
    StudentFunction& operator=(Function function) {
        m_function = std::move(function);
        return *this;
    }

    /// Whether a function was handed over; a pass that is optional asks this first.
    explicit operator bool() const { return static_cast<bool>(m_function); }
    const char* name() const { return m_name; }

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
