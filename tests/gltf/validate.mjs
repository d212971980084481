// Validates a glTF/GLB file with the Khronos glTF validator.
// Usage: node validate.mjs FILE   Prints the report's issues as JSON; exits 1
// if the file has errors, 2 if it cannot be read.
import { readFileSync } from "node:fs";
import { createRequire } from "node:module";

const require = createRequire(import.meta.url);
const validator = require("gltf-validator");

const file = process.argv[2];
let bytes;
try {
  bytes = new Uint8Array(readFileSync(file));
} catch (error) {
  console.error(`validate.mjs: ${file}: ${error.message}`);
  process.exit(2);
}
const report = await validator.validateBytes(bytes, { maxIssues: 100 });
console.log(JSON.stringify({ issues: report.issues, info: report.info }, null, 1));
process.exit(report.issues.numErrors > 0 ? 1 : 0);
