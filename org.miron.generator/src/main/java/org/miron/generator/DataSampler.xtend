package org.miron.generator

import org.eclipse.emf.ecore.EObject
import java.math.BigDecimal
import java.math.MathContext
import java.math.RoundingMode
import java.util.Arrays
import java.util.LinkedHashSet
import java.util.List
import org.miron.dsl.miron.BehaviorTreeLiteral
import org.miron.dsl.miron.ImpactIntensity
import org.miron.dsl.miron.NumericSampledType
import org.miron.dsl.miron.QoSProfiledValue
import org.miron.dsl.miron.SampleValue
import org.miron.dsl.miron.VariationPoint
import org.miron.dsl.roqme.BooleanType
import org.miron.dsl.roqme.EnumType
import org.miron.dsl.roqme.NumericType
import org.miron.dsl.roqme.Property
import org.miron.dsl.util.Types

/**
 * Turns a variation point into value and utility tables (docs/generators.md, "The MiniZinc
 * model"): numbers (lo:prec:hi) become lo, lo+prec, ..., hi (200 steps without a precision), enums
 * the indexes 0..k-1; each impact intensity becomes a utility in [0,100], interpolated linearly
 * between numeric samples and back to neutral (50) at the ends of the range.
 */
class DataSampler {
	/** Steps of a numeric range declared without a precision. */
	public static val DEFAULT_STEPS = 200
	/** Beyond this the solver's tables get large and slow: ask for a coarser precision instead. */
	public static val MAX_VALUES = 20000
	public static val double NEUTRAL = 50.0

	val List<GenerationError> errors

	new(List<GenerationError> errors) {
		this.errors = errors
	}

	/** ---=0, --=100/6, -=200/6, neutral=50, +=400/6, ++=500/6, +++=100. */
	def static double utility(ImpactIntensity intensity) {
		switch intensity {
			case VERY_NEGATIVE: 0.0
			case NEGATIVE: 100.0 / 6
			case SLIGHTLY_NEGATIVE: 200.0 / 6
			case SLIGHTLY_POSITIVE: 400.0 / 6
			case POSITIVE: 500.0 / 6
			case VERY_POSITIVE: 100.0
			default: NEUTRAL
		}
	}

	/** The tables of a varpoint, or null (after reporting why) when it cannot be sampled. */
	def SampledVarpoint sample(VariationPoint vp) {
		val type = Types.dataType(vp as EObject)
		switch type {
			EnumType: sampleEnum(vp, type)
			NumericType: sampleNumber(vp, type)
			BooleanType: sampleBoolean(vp)
			default: {
				errors += new GenerationError(vp, '''varpoint '«vp.name»' cannot be generated: only enum, number and boolean varpoints have a value table''')
				null
			}
		}
	}

	def private sampleEnum(VariationPoint vp, EnumType type) {
		val s = new SampledVarpoint(vp, SampledVarpoint.Kind.ENUM)
		s.step = BigDecimal.ONE
		for (i : 0 ..< type.literals.size) {
			val literal = type.literals.get(i)
			s.literals += literal
			s.values += BigDecimal.valueOf(i)
			if (literal instanceof BehaviorTreeLiteral) {
				if (literal.preset) {
					s.preset = i
				}
			}
		}
		for (i : 0 ..< type.literals.size) {
			val literal = type.literals.get(i)
			if (literal instanceof QoSProfiledValue) {
				for (impact : literal.impacts.filter[property !== null]) {
					table(s, impact.property).set(i, utility(impact.intensity))
				}
			}
		}
		s
	}

	def private sampleBoolean(VariationPoint vp) {
		val s = new SampledVarpoint(vp, SampledVarpoint.Kind.NUMBER)
		s.step = BigDecimal.ONE
		s.values += BigDecimal.ZERO
		s.values += BigDecimal.ONE
		s
	}

	def private sampleNumber(VariationPoint vp, NumericType type) {
		val List<SampleValue> samples = if (type instanceof NumericSampledType)
				type.samples.filter[value !== null].sortBy[value.value].toList
			else
				newArrayList
		val Double lo = type.lower ?: (if(samples.empty) null else samples.head.value.value)
		val Double hi = type.upper ?: (if(samples.empty) null else samples.get(samples.size - 1).value.value)
		if (lo === null || hi === null) {
			errors += new GenerationError(vp, '''numeric varpoint '«vp.name»' needs a range (lo:hi) or samples to know which values it may take''')
			return null
		}
		if (hi < lo) {
			errors += new GenerationError(vp, '''numeric varpoint '«vp.name»' has an empty range: «Numbers.json(lo)» > «Numbers.json(hi)»''')
			return null
		}
		val low = Numbers.clean(lo)
		val high = Numbers.clean(hi)
		val step = if (type.precision !== null && type.precision > 0)
				Numbers.clean(type.precision)
			else if (high.compareTo(low) == 0)
				BigDecimal.ONE
			else
				high.subtract(low).divide(BigDecimal.valueOf(DEFAULT_STEPS), MathContext.DECIMAL64).stripTrailingZeros
		val count = high.subtract(low).divide(step, 0, RoundingMode.FLOOR).longValue + 1
		if (count > MAX_VALUES) {
			errors += new GenerationError(vp, '''numeric varpoint '«vp.name»' would take «count» values (more than «MAX_VALUES»): declare a coarser precision, e.g. («Numbers.json(low)»:«Numbers.json(high.subtract(low).divide(BigDecimal.valueOf(DEFAULT_STEPS), MathContext.DECIMAL64))»:«Numbers.json(high)»)''')
			return null
		}
		val s = new SampledVarpoint(vp, SampledVarpoint.Kind.NUMBER)
		s.step = step
		for (i : 0 ..< count as int) {
			s.values += low.add(step.multiply(BigDecimal.valueOf(i))).stripTrailingZeros
		}
		val properties = new LinkedHashSet<Property>
		for (sample : samples) {
			properties += sample.impacts.map[property].filterNull
		}
		for (p : properties) {
			// Anchors: each sample's utility at its value, neutral at the range ends beyond them.
			val List<Double> xs = newArrayList
			val List<Double> ys = newArrayList
			if (samples.head.value.value > lo) {
				xs += lo
				ys += NEUTRAL
			}
			for (sample : samples) {
				xs += sample.value.value
				ys += utilityOf(sample, p)
			}
			if (samples.get(samples.size - 1).value.value < hi) {
				xs += hi
				ys += NEUTRAL
			}
			val table = table(s, p)
			for (i : 0 ..< s.size) {
				table.set(i, interpolate(xs, ys, s.values.get(i).doubleValue))
			}
		}
		s
	}

	def private static double utilityOf(SampleValue sample, Property p) {
		val impact = sample.impacts.findFirst[property == p]
		if(impact === null) NEUTRAL else utility(impact.intensity)
	}

	/** Piecewise-linear through (xs, ys), xs ascending; constant outside. */
	def static double interpolate(List<Double> xs, List<Double> ys, double x) {
		if (x <= xs.head) {
			return ys.head
		}
		for (i : 1 ..< xs.size) {
			if (x <= xs.get(i)) {
				val x0 = xs.get(i - 1)
				val x1 = xs.get(i)
				return ys.get(i - 1) + (ys.get(i) - ys.get(i - 1)) * (x - x0) / (x1 - x0)
			}
		}
		ys.get(ys.size - 1)
	}

	def private static double[] table(SampledVarpoint s, Property p) {
		var table = s.utilities.get(p)
		if (table === null) {
			table = newDoubleArrayOfSize(s.size)
			Arrays.fill(table, NEUTRAL)
			s.utilities.put(p, table)
		}
		table
	}
}
