/** The gallery's matter.js programs, in the order the page lists them. */
import { bridge } from './bridge';
import { car } from './car';
import { catapult } from './catapult';
import { cloth } from './cloth';
import { concave } from './concave';
import { newtonsCradle } from './newtons-cradle';
import type { MatterProgram } from './program';
import { pyramid } from './pyramid';
import { ragdolls } from './ragdoll';
import { sensors } from './sensors';
import { slingshot } from './slingshot';
import { softBody } from './soft-body';
import { stack } from './stack';
import { wreckingBall } from './wrecking-ball';

export const programs: MatterProgram[] = [
  stack,
  pyramid,
  newtonsCradle,
  catapult,
  bridge,
  car,
  ragdolls,
  softBody,
  cloth,
  concave,
  sensors,
  slingshot,
  wreckingBall,
];
