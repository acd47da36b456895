// A callback bound to an object (ArduPilot's FUNCTOR_BIND_MEMBER, typed): the object and the
// member function to call on it.
#ifndef AUTOPILOT_AP_FUNCTOR_HPP
#define AUTOPILOT_AP_FUNCTOR_HPP

template <class Object, class Ret, class... Args>
struct Functor {
  Object* object;
  Ret (Object::*method)(Args...);

  Ret operator()(Args... args) const { return (object->*method)(args...); }
};

#endif  // AUTOPILOT_AP_FUNCTOR_HPP
