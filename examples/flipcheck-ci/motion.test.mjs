// An engine's CI test (node --test): the motion file its run wrote, judged by flipcheck.
import { test } from "node:test";
import { readFileSync } from "node:fs";
import { assertPasses } from "flipcheck";

test("the engine's motion passes book-intermediate-0.05", () => {
  const file = process.env.MOTION ?? "motion.csv"; // t,qw,qx,qy,qz and wx,wy,wz or wx_world,…
  assertPasses("book-intermediate-0.05", readFileSync(file, "utf8"), { file });
});
