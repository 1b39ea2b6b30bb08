// Runs an original TF.js graph model (the framework it was published for) on a raw int32 NHWC input and
// writes the float32 output, so the ONNX conversion can be checked against it.
// Usage: node run_tfjs.js MODEL_DIR/model.json INPUT.i32 H W OUTPUT.f32
const fs = require('fs');
const path = require('path');
const tf = require('@tensorflow/tfjs');

async function main() {
  const [modelJson, inputFile, h, w, outputFile] = process.argv.slice(2);
  await tf.setBackend('cpu');
  const model = JSON.parse(fs.readFileSync(modelJson, 'utf8'));
  const specs = [];
  const buffers = [];
  for (const group of model.weightsManifest) {
    specs.push(...group.weights);
    for (const shard of group.paths) buffers.push(fs.readFileSync(path.join(path.dirname(modelJson), shard)));
  }
  const weights = Buffer.concat(buffers);
  const handler = tf.io.fromMemory({
    modelTopology: model.modelTopology, weightSpecs: specs,
    weightData: weights.buffer.slice(weights.byteOffset, weights.byteOffset + weights.length),
    format: model.format, generatedBy: model.generatedBy, convertedBy: model.convertedBy,
    signature: model.signature, userDefinedMetadata: model.userDefinedMetadata,
  });
  const graph = await tf.loadGraphModel(handler);
  const raw = fs.readFileSync(inputFile);
  const input = tf.tensor4d(new Int32Array(raw.buffer, raw.byteOffset, raw.length / 4), [1, +h, +w, 3], 'int32');
  const out = await graph.executeAsync(input);
  const data = await (Array.isArray(out) ? out[0] : out).data();
  fs.writeFileSync(outputFile, Buffer.from(new Float32Array(data).buffer));
  console.log(`${path.basename(modelJson)}: ${data.length} outputs`);
}
main().catch((e) => { console.error(e); process.exit(1); });
