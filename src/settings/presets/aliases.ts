/**
 * The names other programs give the printers and filaments of our tables, so that a name copied from
 * them works wherever a preset is named: `strata slice --printer Ender3`, `new Slicer({ printer:
 * 'creality_ender3' })`, a settings file the page imports, the `strata-slicer/polyslice` module.
 *
 * - Polyslice: the seeds' library's printer and filament names (its `new Printer('Ender3')`, the
 *   `{ printer: 'Ender3', filament: 'GenericPLA' }` of three.js's GCodeExporter).
 * - PrusaSlicer: its vendor bundles' printer model ids and names (written into its G-code and projects as
 *   `printer_model`), and OrcaSlicer's / Bambu Studio's printer names where they differ from ours.
 * - Cura: its machine definition ids.
 *
 * Names are compared as `findPrinter` compares them (case-insensitive; spaces and underscores are one
 * hyphen). Printer names with a trailing nozzle size ("… 0.4 nozzle", as PrusaSlicer and OrcaSlicer name
 * their presets) find the printer when the size is 0.4 mm, the size every printer preset has.
 */

/** Where a name comes from → (foreign name → our preset id). */
export interface ForeignNames {
  readonly printers: Readonly<Record<string, string>>;
  readonly filaments: Readonly<Record<string, string>>;
}

export const POLYSLICE_NAMES: ForeignNames = {
  printers: {
    Ender3: 'creality-ender-3',
    Ender3V2: 'creality-ender-3-v2',
    Ender3Pro: 'creality-ender-3-pro',
    Ender3S1: 'creality-ender-3-s1',
    Ender5: 'creality-ender-5',
    Ender6: 'creality-ender-6',
    CR10: 'creality-cr-10',
    CR10S5: 'creality-cr-10-s5',
    CR6SE: 'creality-cr-6-se',
    CrealityK1: 'creality-k1',
    CrealityK1Max: 'creality-k1-max',
    PrusaI3MK3S: 'prusa-i3-mk3s',
    PrusaMini: 'prusa-mini',
    PrusaMK4: 'prusa-mk4',
    PrusaXL: 'prusa-xl',
    BambuLabX1Carbon: 'bambu-lab-x1c',
    BambuLabP1P: 'bambu-lab-p1p',
    BambuLabA1: 'bambu-lab-a1',
    BambuLabA1Mini: 'bambu-lab-a1-mini',
    AnycubicI3Mega: 'anycubic-i3-mega',
    AnycubicKobra: 'anycubic-kobra',
    ElegooNeptune3: 'elegoo-neptune-3',
    ElegooNeptune3Pro: 'elegoo-neptune-3-pro',
    ElegooNeptune4: 'elegoo-neptune-4',
    ElegooNeptune4Pro: 'elegoo-neptune-4-pro',
    ArtillerySidewinderX1: 'artillery-sidewinder-x1',
    ArtillerySidewinderX2: 'artillery-sidewinder-x2',
    ArtilleryGenius: 'artillery-genius',
    SovolSV06: 'sovol-sv06',
    SovolSV06Plus: 'sovol-sv06-plus',
    Voron24: 'voron-2.4-350',
    KingroonKP3S: 'kingroon-kp3s',
  },
  filaments: {
    GenericPLA: 'pla',
    GenericPETG: 'petg',
    GenericABS: 'abs',
    GenericASA: 'asa',
    GenericTPU: 'tpu-95a',
    GenericNylon: 'nylon',
    PrusamentPLA: 'prusament-pla',
    PrusamentPETG: 'prusament-petg',
    PrusaPETG: 'prusament-petg',
    BambuLabPLABasic: 'bambu-pla-basic',
    BambuLabPLAMatte: 'bambu-pla-matte',
    BambuLabPETGHF: 'bambu-petg-hf',
    BambuLabABS: 'bambu-abs',
    PolymakerPolyLitePLA: 'polymaker-polylite-pla',
    PolymakerPolyTerraPLA: 'polymaker-polyterra-pla',
    PolymakerPolyMaxPLA: 'polymaker-polymax-pla',
    PolymakerPolyLitePETG: 'polymaker-polylite-petg',
    PolymakerPolyFlexTPU95: 'polymaker-polyflex-tpu95',
    HatchboxPLA: 'hatchbox-pla',
    HatchboxPETG: 'hatchbox-petg',
    HatchboxABS: 'hatchbox-abs',
    eSunPLAPlus: 'esun-pla-plus',
    eSunPETG: 'esun-petg',
    eSunABSPlus: 'esun-abs-plus',
    OverturePLA: 'overture-pla',
    OverturePETG: 'overture-petg',
    SunluPLA: 'sunlu-pla',
    SunluPETG: 'sunlu-petg',
    ColorFabbPLAPHA: 'colorfabb-pla-pha',
    ColorFabbNGen: 'colorfabb-ngen',
    NinjaFlexTPU: 'ninjaflex',
    SainSmartTPU: 'sainsmart-tpu',
    '3DXTechCarbonX': '3dxtech-carbonx-pa-cf',
    UltimakerPLA: 'ultimaker-pla',
    UltimakerToughPLA: 'ultimaker-tough-pla',
  },
};

export const PRUSASLICER_NAMES: ForeignNames = {
  printers: {
    ENDER3: 'creality-ender-3',
    ENDER3PRO: 'creality-ender-3-pro',
    'Creality Ender-3 Pro': 'creality-ender-3-pro',
    ENDER3V2: 'creality-ender-3-v2',
    ENDER3S1: 'creality-ender-3-s1',
    ENDER5: 'creality-ender-5',
    ENDER5PLUS: 'creality-ender-5-plus',
    ENDER5S1: 'creality-ender-5-s1',
    ENDER6: 'creality-ender-6',
    CR10: 'creality-cr-10',
    CR10S5: 'creality-cr-10-s5',
    CR6SE: 'creality-cr-6-se',
    MK3S: 'prusa-i3-mk3s',
    'Original Prusa i3 MK3S && MK3S+': 'prusa-i3-mk3s',
    'Original Prusa i3 MK3S': 'prusa-i3-mk3s',
    MK4IS: 'prusa-mk4',
    'Original Prusa MK4 Input Shaper': 'prusa-mk4',
    'Original Prusa MK4': 'prusa-mk4',
    'Original Prusa MK4S': 'prusa-mk4s',
    MINIIS: 'prusa-mini',
    'Original Prusa MINI && MINI+': 'prusa-mini',
    'Original Prusa MINI && MINI+ Input Shaper': 'prusa-mini',
    'Original Prusa MINI': 'prusa-mini',
    XLIS: 'prusa-xl',
    'Original Prusa XL': 'prusa-xl',
    'Original Prusa XL Input Shaper': 'prusa-xl',
    COREONE: 'prusa-core-one',
    I3MEGA: 'anycubic-i3-mega',
    NEPTUNE3: 'elegoo-neptune-3',
    'Elegoo Neptune-3': 'elegoo-neptune-3',
    NEPTUNE3PRO: 'elegoo-neptune-3-pro',
    'Elegoo Neptune-3 Pro': 'elegoo-neptune-3-pro',
    'SV06 PLUS': 'sovol-sv06-plus',
    Voron_v2_350: 'voron-2.4-350',
    Voron_v2_350_afterburner: 'voron-2.4-350',
    'Voron v2 350mm3': 'voron-2.4-350',
    Voron_v0_120: 'voron-0.2',
    'Voron Zero 120mm3': 'voron-0.2',
    VC3_300: 'ratrig-v-core-3-300',
    'RatRig V-Core-3.1 300mm': 'ratrig-v-core-3-300',
    'FLSun Q5': 'flsun-q5',
    // OrcaSlicer and Bambu Studio
    'Bambu Lab X1 Carbon': 'bambu-lab-x1c',
    'Bambu Lab X1': 'bambu-lab-x1c',
    'Voron 2.4 350': 'voron-2.4-350',
    'Voron Trident 300': 'voron-trident-300',
    'Voron 0.2 120': 'voron-0.2',
    'Qidi Q1 Pro': 'qidi-q1-pro',
    'Qidi X-Plus 3': 'qidi-x-plus-3',
  },
  filaments: {
    'Prusament PLA': 'prusament-pla',
    'Prusament PETG': 'prusament-petg',
    'Generic PLA @BBL': 'pla',
    'Bambu PLA Basic': 'bambu-pla-basic',
    'Bambu PLA Matte': 'bambu-pla-matte',
    'Bambu PETG HF': 'bambu-petg-hf',
    'Bambu ABS': 'bambu-abs',
    'Generic FLEX': 'tpu-95a',
    'Generic TPU': 'tpu-95a',
    'Generic PA': 'nylon',
  },
};

export const CURA_NAMES: ForeignNames = {
  printers: {
    creality_ender3: 'creality-ender-3',
    creality_ender3pro: 'creality-ender-3-pro',
    creality_ender3v2: 'creality-ender-3-v2',
    creality_ender3s1: 'creality-ender-3-s1',
    creality_ender3v3se: 'creality-ender-3-v3-se',
    creality_ender5: 'creality-ender-5',
    creality_ender5plus: 'creality-ender-5-plus',
    creality_ender5s1: 'creality-ender-5-s1',
    creality_ender6: 'creality-ender-6',
    creality_cr10: 'creality-cr-10',
    creality_cr10s5: 'creality-cr-10-s5',
    creality_cr6se: 'creality-cr-6-se',
    creality_k1: 'creality-k1',
    creality_k1max: 'creality-k1-max',
    prusa_i3_mk3: 'prusa-i3-mk3s',
    Original_Prusa_i3_MK3S_MK3: 'prusa-i3-mk3s',
    anycubic_i3_mega: 'anycubic-i3-mega',
    anycubic_kobra: 'anycubic-kobra',
    elegoo_neptune_3: 'elegoo-neptune-3',
    elegoo_neptune_3pro: 'elegoo-neptune-3-pro',
    elegoo_neptune_4: 'elegoo-neptune-4',
    elegoo_neptune_4pro: 'elegoo-neptune-4-pro',
    artillery_sidewinder_x1: 'artillery-sidewinder-x1',
    artillery_genius: 'artillery-genius',
    voron2_350: 'voron-2.4-350',
  },
  filaments: {
    generic_pla: 'pla',
    generic_petg: 'petg',
    generic_abs: 'abs',
    generic_tpu: 'tpu-95a',
    generic_nylon: 'nylon',
    generic_pc: 'pc',
    generic_pva: 'pva',
    generic_hips: 'hips',
    generic_cpe: 'cpe',
    generic_pp: 'pp',
    generic_bam: 'bvoh',
    ultimaker_pla: 'ultimaker-pla',
    ultimaker_tough_pla: 'ultimaker-tough-pla',
  },
};

export const FOREIGN_NAMES: Readonly<Record<'polyslice' | 'prusaslicer' | 'cura', ForeignNames>> = {
  polyslice: POLYSLICE_NAMES,
  prusaslicer: PRUSASLICER_NAMES,
  cura: CURA_NAMES,
};

/** A printer another program names that Strata has no preset for: its build volume and why there is none. */
export interface PrinterWithoutPreset {
  readonly name: string;
  /** Build volume X × Y × Z, mm (makers' specifications). */
  readonly size: readonly [number, number, number];
  /** Nozzle and filament diameter, mm. */
  readonly nozzle: number;
  readonly filament: number;
  /**
   * `g-code`: it runs Marlin-style G-code, but Strata has no start and end G-code for it yet;
   * `other`: its firmware does not take Strata's G-code, or it is not a filament printer (`why` says).
   */
  readonly kind: 'g-code' | 'other';
  readonly why: string;
}

/** Printers the seeds' library names with no preset here, keyed by that name. */
export const PRINTERS_WITHOUT_PRESET: Readonly<Record<string, PrinterWithoutPreset>> = {
  UltimakerS5: {
    name: 'UltiMaker S5',
    size: [330, 240, 300],
    nozzle: 0.4,
    filament: 2.85,
    kind: 'other',
    why: "it prints Griffin-flavour G-code (Cura's header with material and nozzle checks), which Strata does not write",
  },
  FlashForgeCreatorPro: {
    name: 'FlashForge Creator Pro',
    size: [225, 145, 150],
    nozzle: 0.4,
    filament: 1.75,
    kind: 'other',
    why: 'its Sailfish firmware prints .x3g files, not G-code',
  },
  MakerbotReplicatorPlus: {
    name: 'MakerBot Replicator+',
    size: [295, 195, 165],
    nozzle: 0.4,
    filament: 1.75,
    kind: 'other',
    why: 'it prints .makerbot files, not G-code',
  },
  FlashforgeAdventurer3: {
    name: 'FlashForge Adventurer 3',
    size: [150, 150, 150],
    nozzle: 0.4,
    filament: 1.75,
    kind: 'other',
    why: "it prints FlashPrint's .gx files",
  },
  AnycubicPhotonMonoX: {
    name: 'Anycubic Photon Mono X',
    size: [192, 120, 245],
    nozzle: 0.05,
    filament: 0,
    kind: 'other',
    why: 'it is a resin (MSLA) printer, not a filament printer',
  },
  Raise3DPro2: {
    name: 'Raise3D Pro2',
    size: [305, 305, 300],
    nozzle: 0.4,
    filament: 1.75,
    kind: 'g-code',
    why: 'Strata has no start and end G-code for it yet',
  },
  QidiXPlus: {
    name: 'QIDI X-Plus',
    size: [270, 200, 200],
    nozzle: 0.4,
    filament: 1.75,
    kind: 'g-code',
    why: 'Strata has no start and end G-code for it yet',
  },
  MonopriceSelectMiniV2: {
    name: 'Monoprice Select Mini V2',
    size: [120, 120, 120],
    nozzle: 0.4,
    filament: 1.75,
    kind: 'g-code',
    why: 'Strata has no start and end G-code for it yet',
  },
  LulzBotMini2: {
    name: 'LulzBot Mini 2',
    size: [160, 160, 180],
    nozzle: 0.5,
    filament: 2.85,
    kind: 'g-code',
    why: "its start G-code (nozzle wiping, probing on the bed's corner washers) is not in Strata yet",
  },
  LulzBotTAZ6: {
    name: 'LulzBot TAZ 6',
    size: [280, 280, 250],
    nozzle: 0.5,
    filament: 2.85,
    kind: 'g-code',
    why: "its start G-code (nozzle wiping, probing on the bed's corner washers) is not in Strata yet",
  },
  AnycubicVyper: {
    name: 'Anycubic Vyper',
    size: [245, 245, 260],
    nozzle: 0.4,
    filament: 1.75,
    kind: 'g-code',
    why: 'Strata has no start and end G-code for it yet',
  },
  AnkerMakeM5: {
    name: 'AnkerMake M5',
    size: [235, 235, 250],
    nozzle: 0.4,
    filament: 1.75,
    kind: 'g-code',
    why: 'Strata has no start and end G-code for it yet',
  },
};

/** Cura's id for a printer without a preset here (the same machines), → the seeds' name above. */
export const CURA_WITHOUT_PRESET: Readonly<Record<string, string>> = {
  ultimaker_s5: 'UltimakerS5',
  anycubic_vyper: 'AnycubicVyper',
};
