// Prints the Khronos glTF-Validator's report summary of each .glb given, one JSON line each:
// {"file", "errors", "warnings", "messages": [first error and warning texts]}.
import { readFileSync } from 'node:fs';
import validator from 'gltf-validator';

for (const file of process.argv.slice(2)) {
  const report = await validator.validateBytes(new Uint8Array(readFileSync(file)), {
    maxIssues: 50,
  });
  const messages = report.issues.messages
    .filter((m) => m.severity <= 1)
    .map((m) => `${m.code} ${m.pointer ?? ''}: ${m.message}`);
  console.log(JSON.stringify({
    file,
    errors: report.issues.numErrors,
    warnings: report.issues.numWarnings,
    vertices: report.info.totalVertexCount,
    animations: report.info.animationCount,
    messages,
  }));
}
