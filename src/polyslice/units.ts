/**
 * The units the seeds' library lets a caller speak in (`lengthUnit`, `speedUnit`, `temperatureUnit`,
 * `angleUnit`, `timeUnit`), converted to and from the ones Strata keeps (mm, mm/s, °C, degrees, ms).
 */
import { StrataError } from '../errors.js';

export const LENGTH_UNITS = ['millimeters', 'inches'] as const;
export const SPEED_UNITS = ['millimeterSecond', 'inchSecond', 'meterSecond'] as const;
export const TEMPERATURE_UNITS = ['celsius', 'fahrenheit', 'kelvin'] as const;
export const ANGLE_UNITS = ['degree', 'radian', 'gradian'] as const;
export const TIME_UNITS = ['milliseconds', 'seconds'] as const;

export type LengthUnit = (typeof LENGTH_UNITS)[number];
export type SpeedUnit = (typeof SPEED_UNITS)[number];
export type TemperatureUnit = (typeof TEMPERATURE_UNITS)[number];
export type AngleUnit = (typeof ANGLE_UNITS)[number];
export type TimeUnit = (typeof TIME_UNITS)[number];

/** What a value measures, and so which unit setting applies to it. */
export type Quantity = 'length' | 'speed' | 'temperature' | 'angle' | 'plain';

export interface Units {
  lengthUnit: LengthUnit;
  speedUnit: SpeedUnit;
  temperatureUnit: TemperatureUnit;
  angleUnit: AngleUnit;
}

const MM_PER_INCH = 25.4;

/** A value in the caller's unit → Strata's (mm, mm/s, °C, degrees). */
export function toInternal(value: number, quantity: Quantity, u: Units): number {
  switch (quantity) {
    case 'length':
      return u.lengthUnit === 'inches' ? value * MM_PER_INCH : value;
    case 'speed':
      return u.speedUnit === 'inchSecond' ? value * MM_PER_INCH : u.speedUnit === 'meterSecond' ? value * 1000 : value;
    case 'temperature':
      return u.temperatureUnit === 'fahrenheit'
        ? ((value - 32) * 5) / 9
        : u.temperatureUnit === 'kelvin'
          ? value - 273.15
          : value;
    case 'angle':
      return u.angleUnit === 'radian' ? (value * 180) / Math.PI : u.angleUnit === 'gradian' ? value * 0.9 : value;
    case 'plain':
      return value;
  }
}

/** A value in Strata's unit → the caller's. */
export function fromInternal(value: number, quantity: Quantity, u: Units): number {
  switch (quantity) {
    case 'length':
      return u.lengthUnit === 'inches' ? value / MM_PER_INCH : value;
    case 'speed':
      return u.speedUnit === 'inchSecond' ? value / MM_PER_INCH : u.speedUnit === 'meterSecond' ? value / 1000 : value;
    case 'temperature':
      return u.temperatureUnit === 'fahrenheit'
        ? (value * 9) / 5 + 32
        : u.temperatureUnit === 'kelvin'
          ? value + 273.15
          : value;
    case 'angle':
      return u.angleUnit === 'radian' ? (value * Math.PI) / 180 : u.angleUnit === 'gradian' ? value / 0.9 : value;
    case 'plain':
      return value;
  }
}

/** A unit name checked against its list (the seeds' `speedUnit` also took any letter case). */
export function checkUnit<T extends string>(option: string, value: unknown, allowed: readonly T[]): T {
  const found =
    typeof value === 'string' ? allowed.find((a) => a.toLowerCase() === value.trim().toLowerCase()) : undefined;
  if (found === undefined)
    throw new StrataError(
      'BAD_SETTING',
      `${option} must be one of ${allowed.join(', ')}, got ${JSON.stringify(value)}`,
    );
  return found;
}
