// case: a wrong answer: the body angular velocity where the lab one is asked for
// replace: lab_angular_velocity
// expect: lab_angular_velocity | fail | expected
// score: lab_angular_velocity 0
namespace rigid {
Vec3 lab_angular_velocity(const Mat3& R, const Mat3& R_dot) { return vee(R.transpose() * R_dot); }
}  // namespace rigid
