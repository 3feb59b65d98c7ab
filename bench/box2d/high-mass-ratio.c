// Solver2D's high mass ratio 2 (a 20 m box of density 1, dropped from 16 m
// above two 1 m boxes 18 m apart, on a static ground box 200 m wide; every
// friction 0.6) in Box2D v3's C API, for comparing with this engine's run of
// the same scene step by step (bench/solver2d.mjs's "high-mass-ratio-2",
// with --trace). Box2D is no dependency: build it from its source in a
// scratch directory as bench/box2d/vertical-stack.c says, then this file:
//
//   cc -O2 -I/tmp/box2d/include bench/box2d/high-mass-ratio.c /tmp/box2d/build/src/libbox2d.a -lm -o /tmp/high-mass-ratio
//
//   /tmp/high-mass-ratio [HERTZ] [FROM] [TO]
//
// HERTZ is the contact frequency (Box2D's default 30), 600 steps of 60 Hz
// with 4 sub-steps. Steps FROM to TO (none by default) print a line a body:
// step, body (1 and 2 the small boxes, 3 the big one, as the bench numbers
// them), x, y, angle, vx, vy. NOSLEEP=1 turns sleeping off. Prints the big
// box's y and angle after the last step, and whether Solver2D's judge
// passes it (y >= 10.85, |angle| < 0.05).
#include "box2d/box2d.h"
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv) {
  float hertz = argc > 1 ? (float)atof(argv[1]) : 30.0f;
  int from = argc > 2 ? atoi(argv[2]) : 1;
  int to = argc > 3 ? atoi(argv[3]) : 0;
  b2WorldDef worldDef = b2DefaultWorldDef();
  worldDef.contactHertz = hertz;
  worldDef.enableSleep = getenv("NOSLEEP") == NULL;
  b2WorldId world = b2CreateWorld(&worldDef);

  b2BodyDef groundDef = b2DefaultBodyDef();
  groundDef.position = (b2Vec2){0.0f, -1.0f};
  b2BodyId ground = b2CreateBody(world, &groundDef);
  b2ShapeDef groundShape = b2DefaultShapeDef();
  groundShape.material.friction = 0.6f;
  b2Polygon groundBox = b2MakeBox(100.0f, 1.0f);
  b2CreatePolygonShape(ground, &groundShape, &groundBox);

  // the bench's order: the small box at -9, the one at 9, the big box
  const float x[3] = {-9.0f, 9.0f, 0.0f}, y[3] = {0.5f, 0.5f, 26.0f}, half[3] = {0.5f, 0.5f, 10.0f};
  b2BodyId bodies[3];
  for (int i = 0; i < 3; i++) {
    b2BodyDef bodyDef = b2DefaultBodyDef();
    bodyDef.type = b2_dynamicBody;
    bodyDef.position = (b2Vec2){x[i], y[i]};
    bodies[i] = b2CreateBody(world, &bodyDef);
    b2ShapeDef shapeDef = b2DefaultShapeDef();
    shapeDef.density = 1.0f;
    shapeDef.material.friction = 0.6f;
    b2Polygon box = b2MakeBox(half[i], half[i]);
    b2CreatePolygonShape(bodies[i], &shapeDef, &box);
  }

  for (int k = 1; k <= 600; k++) {
    b2World_Step(world, 1.0f / 60.0f, 4);
    if (k >= from && k <= to) {
      for (int i = 0; i < 3; i++) {
        b2Vec2 p = b2Body_GetPosition(bodies[i]), v = b2Body_GetLinearVelocity(bodies[i]);
        printf("%d %d %.4f %.4f %.4f %.4f %.4f\n", k, i + 1, p.x, p.y, b2Rot_GetAngle(b2Body_GetRotation(bodies[i])), v.x, v.y);
      }
    }
  }
  b2Vec2 p = b2Body_GetPosition(bodies[2]);
  float angle = b2Rot_GetAngle(b2Body_GetRotation(bodies[2]));
  printf("contacts %.1f Hz: the big box at y %.4f, angle %.5f: %s\n", hertz, p.y, angle,
         p.y >= 10.85f && angle > -0.05f && angle < 0.05f ? "passes" : "fails");
  b2DestroyWorld(world);
  return 0;
}
