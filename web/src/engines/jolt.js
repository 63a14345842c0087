// Jolt (jolt-physics: C++ compiled to WebAssembly, single precision, the WebAssembly inlined as
// base64) as two models of the page, without and with its gyroscopic term
// (BodyCreationSettings.mApplyGyroscopicForce). One dynamic box body whose mass and inertia are
// given (EOverrideMassProperties_MassAndInertiaProvided: diag(Ix, Iy, Iz), not the box's), no
// gravity, no damping, no sleeping, no angular velocity limit, JoltInterface.Step(dt, 1).
import initJolt from 'jolt-physics/wasm-compat';
import { ENGINE_MODEL } from './models.js';

function joltAdapter(model, label, gyroscopic) {
  return {
    model,
    package: 'jolt-physics',
    mode: gyroscopic ? 'gyroscopic' : '',
    label,
    load() {
      if (!this.module) this.module = initJolt();
      return this.module.then((Jolt) => { this.Jolt = Jolt; });
    },
    start(body, dt) {
      const Jolt = this.Jolt;
      const keep = [];  // what this run allocated, destroyed by dispose()
      const make = (x) => { keep.push(x); return x; };
      const settings = new Jolt.JoltSettings();
      const pairs = new Jolt.ObjectLayerPairFilterTable(1);
      const layers = new Jolt.BroadPhaseLayerInterfaceTable(1, 1);
      layers.MapObjectToBroadPhaseLayer(0, new Jolt.BroadPhaseLayer(0));
      settings.mObjectLayerPairFilter = pairs;
      settings.mBroadPhaseLayerInterface = layers;
      settings.mObjectVsBroadPhaseLayerFilter = new Jolt.ObjectVsBroadPhaseLayerFilterTable(layers, 1, pairs, 1);
      const jolt = new Jolt.JoltInterface(settings);
      Jolt.destroy(settings);
      const system = jolt.GetPhysicsSystem();
      system.SetGravity(make(new Jolt.Vec3(0, 0, 0)));
      const bodies = system.GetBodyInterface();
      const [a, b, c] = body.size;
      const shape = new Jolt.BoxShape(make(new Jolt.Vec3(a / 2, b / 2, c / 2)), 0.05 * Math.min(a, b, c), null);
      const create = make(new Jolt.BodyCreationSettings(shape, make(new Jolt.RVec3(0, 0, 0)),
        make(new Jolt.Quat(0, 0, 0, 1)), Jolt.EMotionType_Dynamic, 0));
      create.mOverrideMassProperties = Jolt.EOverrideMassProperties_MassAndInertiaProvided;
      const [ix, iy, iz] = body.moments;
      create.mMassPropertiesOverride.mMass = body.mass;
      create.mMassPropertiesOverride.mInertia = make(new Jolt.Mat44()).sScaleVec3(make(new Jolt.Vec3(ix, iy, iz)));
      create.mLinearDamping = 0;
      create.mAngularDamping = 0;
      create.mGravityFactor = 0;
      create.mAllowSleeping = false;
      create.mMaxAngularVelocity = 1e30;
      create.mApplyGyroscopicForce = gyroscopic;
      const [wx, wy, wz] = body.omega0;
      create.mAngularVelocity = make(new Jolt.Vec3(wx, wy, wz));
      const rigid = bodies.CreateBody(create);
      const id = rigid.GetID();
      bodies.AddBody(id, Jolt.EActivation_Activate);
      return {
        step: () => jolt.Step(dt, 1),
        quaternion: () => { const q = rigid.GetRotation(); return [q.GetW(), q.GetX(), q.GetY(), q.GetZ()]; },
        omegaWorld: () => { const w = rigid.GetAngularVelocity(); return [w.GetX(), w.GetY(), w.GetZ()]; },
        dispose() {
          bodies.RemoveBody(id);
          bodies.DestroyBody(id);
          for (const x of keep) Jolt.destroy(x);
          Jolt.destroy(jolt);
        },
      };
    },
  };
}

export const jolt = joltAdapter(ENGINE_MODEL.jolt, 'Jolt 1.1', false);
export const joltGyroscopic = joltAdapter(ENGINE_MODEL.joltGyroscopic, 'Jolt 1.1, mApplyGyroscopicForce', true);
