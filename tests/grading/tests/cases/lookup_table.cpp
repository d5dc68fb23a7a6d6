// case: a lookup table of the public answers: hat's graders and their random inputs are public, so a table of the reference's output for each input they send (21 inputs, made by running the graders with the public seed) passes with the public seed; with the instructor's --seed it does not earn the exercise
// replace: hat
// expect: hat | pass
// seeded: hat | pass
// seeded: hat: hat(w) x equals the cross product | fail | expected
#include <array>
namespace {
struct Row {
    std::array<double, 3> in;
    std::array<double, 9> out;
};
// Each input hat's graders send with the public seed, and the reference's answer, bit for bit.
const Row table[] = {
    {{-0x1.261fd98a3339ap-2, -0x1.2f4752dd08f1dp+0, 0x1.3c87a35d37933p+0},
     {0.0, -0x1.3c87a35d37933p+0, -0x1.2f4752dd08f1dp+0, 0x1.3c87a35d37933p+0, 0.0, 0x1.261fd98a3339ap-2,
      0x1.2f4752dd08f1dp+0, -0x1.261fd98a3339ap-2, 0.0}},
    {{-0x1.392a6d58927f9p+0, 0x1.4c897be0c2daep+1, -0x1.36c83e70d6d2cp+1},
     {0.0, 0x1.36c83e70d6d2cp+1, 0x1.4c897be0c2daep+1, -0x1.36c83e70d6d2cp+1, 0.0, 0x1.392a6d58927f9p+0,
      -0x1.4c897be0c2daep+1, -0x1.392a6d58927f9p+0, 0.0}},
    {{-0x1.53871b6957316p+0, 0x1.e2a613456e6bdp+0, -0x1.f41eb36b4a1cap+0},
     {0.0, 0x1.f41eb36b4a1cap+0, 0x1.e2a613456e6bdp+0, -0x1.f41eb36b4a1cap+0, 0.0, 0x1.53871b6957316p+0,
      -0x1.e2a613456e6bdp+0, -0x1.53871b6957316p+0, 0.0}},
    {{-0x1.5a514c7eaf291p+1, 0x1.04bfbf42769cep+0, 0x1.f9b21769b826ep+0},
     {0.0, -0x1.f9b21769b826ep+0, 0x1.04bfbf42769cep+0, 0x1.f9b21769b826ep+0, 0.0, 0x1.5a514c7eaf291p+1,
      -0x1.04bfbf42769cep+0, -0x1.5a514c7eaf291p+1, 0.0}},
    {{-0x1.61b00c1824521p+1, -0x1.28450018fc020p+1, 0x1.305f5cd3cc9a0p+1},
     {0.0, -0x1.305f5cd3cc9a0p+1, -0x1.28450018fc020p+1, 0x1.305f5cd3cc9a0p+1, 0.0, 0x1.61b00c1824521p+1,
      0x1.28450018fc020p+1, -0x1.61b00c1824521p+1, 0.0}},
    {{-0x1.65957db5d013ap+1, 0x1.f30bc4fba6fcep-1, 0x1.7bca3ca780990p-4},
     {0.0, -0x1.7bca3ca780990p-4, 0x1.f30bc4fba6fcep-1, 0x1.7bca3ca780990p-4, 0.0, 0x1.65957db5d013ap+1,
      -0x1.f30bc4fba6fcep-1, -0x1.65957db5d013ap+1, 0.0}},
    {{-0x1.7a15a098a727ep+1, 0x1.440edd2589854p+1, -0x1.174965efbfd70p-3},
     {0.0, 0x1.174965efbfd70p-3, 0x1.440edd2589854p+1, -0x1.174965efbfd70p-3, 0.0, 0x1.7a15a098a727ep+1,
      -0x1.440edd2589854p+1, -0x1.7a15a098a727ep+1, 0.0}},
    {{-0x1.b493a5b5b8e46p+0, -0x1.41dd2869fe5c6p+0, 0x1.0d89b7c6a2d4fp+1},
     {0.0, -0x1.0d89b7c6a2d4fp+1, -0x1.41dd2869fe5c6p+0, 0x1.0d89b7c6a2d4fp+1, 0.0, 0x1.b493a5b5b8e46p+0,
      0x1.41dd2869fe5c6p+0, -0x1.b493a5b5b8e46p+0, 0.0}},
    {{-0x1.e98485190fd00p+0, 0x1.4a5f0721602a3p+0, 0x1.b193debdaf5fbp+0},
     {0.0, -0x1.b193debdaf5fbp+0, 0x1.4a5f0721602a3p+0, 0x1.b193debdaf5fbp+0, 0.0, 0x1.e98485190fd00p+0,
      -0x1.4a5f0721602a3p+0, -0x1.e98485190fd00p+0, 0.0}},
    {{0x1.069877e92b490p-3, 0x1.9cabfa95fd574p-2, -0x1.9368170f4b724p+0},
     {0.0, 0x1.9368170f4b724p+0, 0x1.9cabfa95fd574p-2, -0x1.9368170f4b724p+0, 0.0, -0x1.069877e92b490p-3,
      -0x1.9cabfa95fd574p-2, 0x1.069877e92b490p-3, 0.0}},
    {{0x1.1f1b92edc167ep+1, 0x1.a332eaac798e8p-1, -0x1.661fb2671c68ap+1},
     {0.0, 0x1.661fb2671c68ap+1, 0x1.a332eaac798e8p-1, -0x1.661fb2671c68ap+1, 0.0, -0x1.1f1b92edc167ep+1,
      -0x1.a332eaac798e8p-1, 0x1.1f1b92edc167ep+1, 0.0}},
    {{0x1.3333333333333p-2, -0x1.b333333333333p+0, 0x1.4000000000000p+1},
     {0.0, -0x1.4000000000000p+1, -0x1.b333333333333p+0, 0x1.4000000000000p+1, 0.0, -0x1.3333333333333p-2,
      0x1.b333333333333p+0, 0x1.3333333333333p-2, 0.0}},
    {{0x1.3b44c321fe11ap+1, -0x1.6fca125de6ca4p-2, -0x1.97c5d8cba8594p-1},
     {0.0, 0x1.97c5d8cba8594p-1, -0x1.6fca125de6ca4p-2, -0x1.97c5d8cba8594p-1, 0.0, -0x1.3b44c321fe11ap+1,
      0x1.6fca125de6ca4p-2, 0x1.3b44c321fe11ap+1, 0.0}},
    {{0x1.4f72607ed2220p-4, 0x1.58db5e370b6bap+0, -0x1.050f3653de238p+1},
     {0.0, 0x1.050f3653de238p+1, 0x1.58db5e370b6bap+0, -0x1.050f3653de238p+1, 0.0, -0x1.4f72607ed2220p-4,
      -0x1.58db5e370b6bap+0, 0x1.4f72607ed2220p-4, 0.0}},
    {{0x1.6680640c867ecp-2, -0x1.ed7aa46bd14bfp-1, -0x1.aa39c6d60a6a0p-3},
     {0.0, 0x1.aa39c6d60a6a0p-3, -0x1.ed7aa46bd14bfp-1, -0x1.aa39c6d60a6a0p-3, 0.0, -0x1.6680640c867ecp-2,
      0x1.ed7aa46bd14bfp-1, 0x1.6680640c867ecp-2, 0.0}},
    {{0x1.6ed160da1d054p-1, -0x1.41415402a4a8ep+0, -0x1.3258d9a002d1bp-1},
     {0.0, 0x1.3258d9a002d1bp-1, -0x1.41415402a4a8ep+0, -0x1.3258d9a002d1bp-1, 0.0, -0x1.6ed160da1d054p-1,
      0x1.41415402a4a8ep+0, 0x1.6ed160da1d054p-1, 0.0}},
    {{0x1.6ef97a2240b84p-2, -0x1.407d1b5aea982p+0, 0x1.84fb80c370540p-4},
     {0.0, -0x1.84fb80c370540p-4, -0x1.407d1b5aea982p+0, 0x1.84fb80c370540p-4, 0.0, -0x1.6ef97a2240b84p-2,
      0x1.407d1b5aea982p+0, 0x1.6ef97a2240b84p-2, 0.0}},
    {{0x1.7bd2daf74470bp+0, -0x1.79373a1ab60e2p-1, -0x1.1190a8ca5aebep+0},
     {0.0, 0x1.1190a8ca5aebep+0, -0x1.79373a1ab60e2p-1, -0x1.1190a8ca5aebep+0, 0.0, -0x1.7bd2daf74470bp+0,
      0x1.79373a1ab60e2p-1, 0x1.7bd2daf74470bp+0, 0.0}},
    {{0x1.c465dfbc81bc9p+0, 0x1.2a6b475d4489fp+0, 0x1.7ca9eb8adf658p+1},
     {0.0, -0x1.7ca9eb8adf658p+1, 0x1.2a6b475d4489fp+0, 0x1.7ca9eb8adf658p+1, 0.0, -0x1.c465dfbc81bc9p+0,
      -0x1.2a6b475d4489fp+0, 0x1.c465dfbc81bc9p+0, 0.0}},
    {{0x1.cbab1a0c93aeap+0, -0x1.467a07aa389c2p+1, -0x1.5a15020f8c590p+0},
     {0.0, 0x1.5a15020f8c590p+0, -0x1.467a07aa389c2p+1, -0x1.5a15020f8c590p+0, 0.0, -0x1.cbab1a0c93aeap+0,
      0x1.467a07aa389c2p+1, 0x1.cbab1a0c93aeap+0, 0.0}},
    {{0x1.e8ac0b8dc9b08p-1, -0x1.5d4b7e5276e4cp+0, -0x1.13361cfdb03c9p-1},
     {0.0, 0x1.13361cfdb03c9p-1, -0x1.5d4b7e5276e4cp+0, -0x1.13361cfdb03c9p-1, 0.0, -0x1.e8ac0b8dc9b08p-1,
      0x1.5d4b7e5276e4cp+0, 0x1.e8ac0b8dc9b08p-1, 0.0}},
};
}  // namespace
namespace rigid {
Mat3 hat(const Vec3& w) {
    for (const Row& r : table)
        if (r.in[0] == w.x() && r.in[1] == w.y() && r.in[2] == w.z())
            return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(r.out.data());
    return Mat3::Zero();
}
}  // namespace rigid
