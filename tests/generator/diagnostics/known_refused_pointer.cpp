// An estimator holding a view on the heap through a pointer to a polymorphic class restore
// cannot create (no default constructor), and nothing of that class in the state for the
// pointer to refer to: every checkpoint taken while it is set would be refused, so generation
// is an error naming the member and the fixes. known_refused_pointer.symcr skips the member:
// generation then succeeds.
struct View {
  explicit View(int rotation) : rotation(rotation) {}
  virtual ~View() {}
  virtual int yaw() const { return rotation; }
  int rotation;
};
struct Ahrs {
  float roll = 0, pitch = 0, yaw = 0;
  View* _view = nullptr;
};
struct Vehicle {
  Ahrs ahrs;
  int ticks = 0;
};
Vehicle vehicle;
