/**
 * `strata-slicer/polyslice`: the seeds' library's API (`Polyslice`, `Printer`, `Filament`) over Strata, so
 * that code written for it, three.js's GCodeExporter among it, runs by changing one import:
 *
 *   import { Polyslice, Printer, Filament } from 'strata-slicer/polyslice';
 *   const slicer = new Polyslice({ printer: new Printer('Ender3'), filament: new Filament('GenericPLA') });
 *   const gcode = slicer.slice(mesh);
 *
 * The default export is `Polyslice`, which also carries `Polyslice.Polyslice`, `.Printer` and `.Filament`
 * (as the seeds' library's does: `const { Polyslice, Printer, Filament } = require(...)` and the exporter's
 * `Polyslice.Polyslice` both work).
 */
import { Filament, listAvailableFilaments } from './filament.js';
import { Polyslice } from './polyslice.js';
import { listAvailablePrinters, Printer } from './printer.js';

export { Polyslice, Printer, Filament, listAvailablePrinters, listAvailableFilaments };
export type { PolysliceOptions, PolysliceSettings, ProgressInfo } from './polyslice.js';
export type { Nozzle } from './printer.js';

Object.assign(Polyslice, { Polyslice, Printer, Filament, listAvailablePrinters, listAvailableFilaments });

export default Polyslice as typeof Polyslice & {
  Polyslice: typeof Polyslice;
  Printer: typeof Printer;
  Filament: typeof Filament;
  listAvailablePrinters: typeof listAvailablePrinters;
  listAvailableFilaments: typeof listAvailableFilaments;
};
