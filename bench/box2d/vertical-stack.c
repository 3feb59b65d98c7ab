// The vertical stack (Solver2D's numbers: 15 boxes of 1 m, mu 0.3,
// each 0.01 m off centre alternately, on a static ground box 200 m wide) in
// Box2D v3's C API, for comparing with this engine's run of the same scene
// (bench/solver2d.mjs's "vertical-stack", at the same g*dt^2/h and contact
// frequency). Box2D is no dependency: build it from its source in a scratch
// directory and this file against it:
//
//   git clone https://github.com/erincatto/box2d /tmp/box2d   (or an archive of it)
//   cmake -S /tmp/box2d -B /tmp/box2d/build -DCMAKE_BUILD_TYPE=Release
//         -DBOX2D_SAMPLES=OFF -DBOX2D_UNIT_TESTS=OFF -DBOX2D_VALIDATE=OFF   (one line)
//   cmake --build /tmp/box2d/build --target box2d -j2
//   cc -O2 -I/tmp/box2d/include bench/box2d/vertical-stack.c /tmp/box2d/build/src/libbox2d.a -lm -o /tmp/vertical-stack
//
//   /tmp/vertical-stack [HERTZ] [STEPS] [EVERY]
//
// HERTZ is the contact frequency (Box2D's default 30; Box2D caps it at an
// eighth of the sub-step rate, 30 at 60 Hz steps of 4 sub-steps), STEPS
// the 60 Hz steps (600: 10 s), EVERY > 0 prints the top box every EVERY
// steps. In the environment: NORECYCLE=1 turns off Box2D's contact
// recycling (a pair's manifold kept while the pair moves little), NOSLEEP=1
// sleeping, NOWARM=1 warm starting, FRICTION=x sets every shape's friction,
// BOXES=n stacks n boxes instead of 15 (1 to 100). Prints the top box's x,
// y and speed after the last step, and whether it stands as Solver2D judges
// it (|dx| < 0.25, y n - 0.5 +- 0.1, speed < 0.05).
#include "box2d/box2d.h"
#include <stdio.h>
#include <stdlib.h>

#define MAX_BOXES 100

int main(int argc, char **argv) {
  float hertz = argc > 1 ? (float)atof(argv[1]) : 30.0f;
  int steps = argc > 2 ? atoi(argv[2]) : 600;
  int every = argc > 3 ? atoi(argv[3]) : 0;
  int recycle = getenv("NORECYCLE") == NULL;
  int n = getenv("BOXES") ? atoi(getenv("BOXES")) : 15;
  if (n < 1 || n > MAX_BOXES) {
    fprintf(stderr, "BOXES must be a whole number from 1 to %d\n", MAX_BOXES);
    return 2;
  }
  b2WorldDef worldDef = b2DefaultWorldDef();
  worldDef.contactHertz = hertz;
  worldDef.enableSleep = getenv("NOSLEEP") == NULL;
  b2WorldId world = b2CreateWorld(&worldDef);
  if (getenv("NOWARM")) b2World_EnableWarmStarting(world, false);

  b2BodyDef groundDef = b2DefaultBodyDef();
  groundDef.position = (b2Vec2){0.0f, -1.0f};
  groundDef.enableContactRecycling = recycle;
  b2BodyId ground = b2CreateBody(world, &groundDef);
  b2ShapeDef groundShape = b2DefaultShapeDef();
  if (getenv("FRICTION")) groundShape.material.friction = (float)atof(getenv("FRICTION"));
  b2Polygon groundBox = b2MakeBox(100.0f, 1.0f);
  b2CreatePolygonShape(ground, &groundShape, &groundBox);

  b2BodyId boxes[MAX_BOXES];
  b2Polygon box = b2MakeBox(0.5f, 0.5f);
  for (int i = 0; i < n; i++) {
    b2BodyDef bodyDef = b2DefaultBodyDef();
    bodyDef.type = b2_dynamicBody;
    bodyDef.enableContactRecycling = recycle;
    bodyDef.position = (b2Vec2){i % 2 == 0 ? -0.01f : 0.01f, 0.5f + (float)i};
    boxes[i] = b2CreateBody(world, &bodyDef);
    b2ShapeDef shapeDef = b2DefaultShapeDef();
    shapeDef.density = 1.0f;
    shapeDef.material.friction = getenv("FRICTION") ? (float)atof(getenv("FRICTION")) : 0.3f;
    b2CreatePolygonShape(boxes[i], &shapeDef, &box);
  }

  for (int k = 1; k <= steps; k++) {
    b2World_Step(world, 1.0f / 60.0f, 4);
    if (every > 0 && k % every == 0) {
      b2Vec2 p = b2Body_GetPosition(boxes[n - 1]);
      printf("%d %.5f %.5f\n", k, p.x, p.y);
    }
  }
  b2Vec2 p = b2Body_GetPosition(boxes[n - 1]);
  float speed = b2Length(b2Body_GetLinearVelocity(boxes[n - 1]));
  float dx = p.x - 0.01f * ((n - 1) % 2 == 0 ? -1.0f : 1.0f);
  float top = (float)n - 0.5f;
  int stands = dx > -0.25f && dx < 0.25f && p.y > top - 0.1f && p.y < top + 0.1f && speed < 0.05f;
  printf("%d boxes, contacts %.1f Hz%s: top box x %.4f y %.4f speed %.4f: %s\n", n, hertz, recycle ? "" : ", not recycled",
         p.x, p.y, speed, stands ? "stands" : (dx > -0.25f && dx < 0.25f ? "upright, compressed" : "falls"));
  b2DestroyWorld(world);
  return 0;
}
