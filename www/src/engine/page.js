// The page's own planner, a bundle of its own (`page-engine.js` beside
// `app.js`): fetched only when the app plans on the page (`?engine=page`, or
// a browser without a drawing worker), so a first diagram drawn in the
// worker does not carry it.

export * as glue from '../../pkg/screwcut.js';
export { Engine, toolsLoader } from './engine.js';
