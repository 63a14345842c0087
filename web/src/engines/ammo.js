// Ammo.js (ammo.js: Bullet compiled by emscripten to asm.js, single precision) as a model run
// under node by web/flipcheck-engines.mjs. One btRigidBody in a btDiscreteDynamicsWorld with no
// gravity; its mass and local inertia given (btRigidBodyConstructionInfo(mass, motion state,
// shape, diag(Ix, Iy, Iz)): the box shape's own inertia is never computed), linear and angular
// damping 0 (setDamping), no sleeping (sleeping thresholds 0 and DISABLE_DEACTIVATION), one
// step of dt per call (stepSimulation(dt, 0): no substeps, no interpolation). This build binds
// no btRigidBody::setFlags, so the gyroscopic option cannot be chosen: one mode, the build's
// default (measured in docs/flipcheck.md: it turns over, losing energy, as an implicit
// gyroscopic step does). Bullet limits the rotation per step to π/4 (ANGULAR_MOTION_THRESHOLD
// in btTransformUtil, not settable), far above any scenario's ω·dt.
import { createRequire } from 'node:module';
import { NODE_ENGINE_MODEL } from './models.js';

const DISABLE_DEACTIVATION = 4;  // btCollisionObject.h's activation state

export const ammo = {
  model: NODE_ENGINE_MODEL.ammo,
  package: 'ammo.js',
  mode: '',
  label: 'Ammo.js',
  load() {
    this.A = createRequire(import.meta.url)('ammo.js');
    return Promise.resolve();
  },
  start(body, dt) {
    const A = this.A;
    const keep = [];
    const make = (x) => { keep.push(x); return x; };
    const config = make(new A.btDefaultCollisionConfiguration());
    const dispatcher = make(new A.btCollisionDispatcher(config));
    const broadphase = make(new A.btDbvtBroadphase());
    const solver = make(new A.btSequentialImpulseConstraintSolver());
    const world = new A.btDiscreteDynamicsWorld(dispatcher, broadphase, solver, config);
    world.setGravity(make(new A.btVector3(0, 0, 0)));
    const [a, b, c] = body.size;
    const shape = make(new A.btBoxShape(make(new A.btVector3(a / 2, b / 2, c / 2))));
    const start = make(new A.btTransform());
    start.setIdentity();
    const motion = make(new A.btDefaultMotionState(start));
    const [ix, iy, iz] = body.moments;
    const info = make(new A.btRigidBodyConstructionInfo(body.mass, motion, shape, make(new A.btVector3(ix, iy, iz))));
    info.set_m_linearDamping(0);
    info.set_m_angularDamping(0);
    info.set_m_additionalDamping(false);
    info.set_m_linearSleepingThreshold(0);
    info.set_m_angularSleepingThreshold(0);
    const rigid = new A.btRigidBody(info);
    rigid.setDamping(0, 0);
    rigid.setSleepingThresholds(0, 0);
    rigid.forceActivationState(DISABLE_DEACTIVATION);
    world.addRigidBody(rigid);
    const [wx, wy, wz] = body.omega0;
    rigid.setAngularVelocity(make(new A.btVector3(wx, wy, wz)));
    return {
      step: () => world.stepSimulation(dt, 0),
      quaternion: () => {
        const q = rigid.getWorldTransform().getRotation();
        return [q.w(), q.x(), q.y(), q.z()];
      },
      omegaWorld: () => { const w = rigid.getAngularVelocity(); return [w.x(), w.y(), w.z()]; },
      dispose() {
        world.removeRigidBody(rigid);
        A.destroy(rigid);
        A.destroy(world);
        for (const x of keep.reverse()) A.destroy(x);
      },
    };
  },
};
