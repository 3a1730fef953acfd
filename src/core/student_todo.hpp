/// @file student_todo.hpp
/// @brief studentTodo(): what the unwritten part of a student template does when it runs.
///
/// Each template in lectures/student-template/ is an engine file with the
/// code a lecture asks for replaced by a TODO that calls studentTodo(). Until
/// that code is written, the first call stops the run with a message that
/// names the function and says what to write, e.g.
///
///     student stage not written yet: stepwise::integrateSymplecticEuler
///     (integrators/symplectic_euler.cpp): v += h*a, then x += h*v ...
///
/// A test that reaches it fails with that message (Catch2 prints the
/// exception), instead of failing later on a number that looks wrong.
#pragma once

#include <stdexcept>
#include <string>

namespace stepwise {

/// @brief The start of every message studentTodo() throws.
inline constexpr const char* kStudentTodoPrefix = "student stage not written yet: ";

/// @brief Throws std::logic_error(kStudentTodoPrefix + @p what): the stage a student has not written yet.
///
/// `Result` lets the call stand where a value is expected,
/// `const Real vc = studentTodo<Real>("…", vn);`. The arguments after the
/// message are ignored: an unwritten function passes its parameters, so that
/// it compiles without "unused parameter" warnings until its code is written.
/// @param what the function (`stepwise::name`), its file and what to write there
template <class Result = void, class... Unused>
[[noreturn]] Result studentTodo(const char* what, const Unused&... /*parameters*/) {
    throw std::logic_error(std::string(kStudentTodoPrefix) + what);
}

}  // namespace stepwise
