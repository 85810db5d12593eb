package org.miron.generator

import org.eclipse.emf.ecore.EObject
import org.eclipse.xtext.nodemodel.util.NodeModelUtils
import java.util.LinkedHashSet
import java.util.List
import java.util.Map
import java.util.Set
import org.miron.dsl.miron.VariationPoint
import org.miron.dsl.roqme.BeliefExpression
import org.miron.dsl.roqme.BinaryExpression
import org.miron.dsl.roqme.BinaryOperator
import org.miron.dsl.roqme.BooleanValue
import org.miron.dsl.roqme.ConditionalExpression
import org.miron.dsl.roqme.Context
import org.miron.dsl.roqme.EnumType
import org.miron.dsl.roqme.EnumValue
import org.miron.dsl.roqme.EventValue
import org.miron.dsl.roqme.Expression
import org.miron.dsl.roqme.FunctionCall
import org.miron.dsl.roqme.NumericValue
import org.miron.dsl.roqme.Param
import org.miron.dsl.roqme.Property
import org.miron.dsl.roqme.UnaryExpression
import org.miron.dsl.roqme.VariableRef
import org.miron.dsl.roqme.BooleanType
import org.miron.dsl.roqme.EventType
import org.miron.dsl.roqme.NumericType
import org.miron.dsl.roqme.TimeType
import org.miron.dsl.util.Types

/**
 * Translates the RoQME expressions of MIRoN rules to MiniZinc. Contexts and properties become
 * parameters (context_&lt;ns&gt;_&lt;c&gt;, metric_&lt;ns&gt;_&lt;p&gt;), varpoints their decision
 * (enum: the index &lt;vp&gt;_var, number: &lt;vp&gt;_x[&lt;vp&gt;_var]), enum literals their
 * 0-based index, and "=" on a numeric varpoint means "within half a step" so that a value between
 * two samples still selects the nearest one. What has no MiniZinc meaning (event patterns,
 * timers, windows over time) is reported as a GenerationError on the offending expression.
 */
class ExpressionToMiniZinc {
	/** What one expression reads: the rule guards use it. */
	static class Mentions {
		public val Set<Context> contexts = new LinkedHashSet
		public val Set<SampledVarpoint> varpoints = new LinkedHashSet
	}

	val Map<VariationPoint, SampledVarpoint> varpoints
	val List<GenerationError> errors
	/** Every property and context any translated expression read, in order of first mention. */
	public val Set<Property> properties = new LinkedHashSet
	public val Set<Context> contexts = new LinkedHashSet

	new(Map<VariationPoint, SampledVarpoint> varpoints, List<GenerationError> errors) {
		this.varpoints = varpoints
		this.errors = errors
	}

	def String translate(Expression e, Mentions m) {
		switch e {
			BinaryExpression: binary(e, m).toString
			UnaryExpression: unary(e, m).toString
			ConditionalExpression: '''(if «translate(e.condition, m)» then «translate(e.ifTrue, m)» else «translate(e.ifFalse, m)» endif)'''.toString
			VariableRef: reference(e, m)
			BeliefExpression:
				if (e.belief instanceof Property) metric(e.belief as Property) else unsupported(e, "only properties have a MiniZinc parameter (metric_...)")
			NumericValue: Numbers.mzn(e.value)
			BooleanValue: String.valueOf(e.value)
			EventValue: "true"
			EnumValue: enumIndex(e)
			FunctionCall: function(e, m).toString
			default: unsupported(e, "rules may use numbers, booleans, enum literals, contexts, properties, varpoints, arithmetic, comparisons, and/or/not, ?: and abs/sqrt/exp/pow/min/max")
		}
	}

	def private binary(BinaryExpression e, Mentions m) {
		val op = e.operator
		if (op == BinaryOperator.EQ || op == BinaryOperator.NE) {
			val vp = numericVarpoint(e.left) ?: numericVarpoint(e.right)
			if (vp !== null) {
				// Within half a step of the wanted value: the nearest sample is selected.
				val other = if (numericVarpoint(e.left) !== null) e.right else e.left
				m.varpoints += vp
				val distance = '''abs(«vp.x»[«vp.decision»] - «translate(other, m)»)'''
				val half = Numbers.mzn(vp.step.doubleValue / 2)
				return if (op == BinaryOperator.EQ) '''(«distance» <= «half»)''' else '''(«distance» > «half»)'''
			}
		}
		val symbol = switch op {
			case OR, case LOGICAL_OR: "\\/"
			case AND, case LOGICAL_AND: "/\\"
			case EQ: "="
			case NE: "!="
			case LT: "<"
			case GT: ">"
			case LE: "<="
			case GE: ">="
			case PLUS: "+"
			case MINUS: "-"
			case TIMES: "*"
			case DIVIDE: "/"
			default: null
		}
		if (symbol === null) {
			return unsupported(e, "event patterns ('" + op.literal + "') belong in RoQME observations, not in rules")
		}
		'''(«translate(e.left, m)» «symbol» «translate(e.right, m)»)'''
	}

	def private unary(UnaryExpression e, Mentions m) {
		switch e.operator {
			case NOT, case LOGICAL_NOT: '''(not «translate(e.term, m)»)'''
			case MINUS: '''(-«translate(e.term, m)»)'''
			case ONCE: unsupported(e, "event patterns ('once') belong in RoQME observations, not in rules")
			default: unsupported(e, "'" + e.operator.literal + "' has no MiniZinc translation")
		}
	}

	def private String reference(VariableRef e, Mentions m) {
		val v = e.variable
		switch v {
			Property:
				metric(v)
			Context: {
				val type = Types.dataType(v as EObject)
				if (type instanceof TimeType || type === null) {
					return unsupported(e, "context '" + v.name + "' has a type without MiniZinc parameter (time)")
				}
				contexts += v
				m.contexts += v
				Names.context(v)
			}
			VariationPoint: {
				val vp = varpoints.get(v)
				if (vp === null) {
					return unsupported(e, "varpoint '" + v.name + "' has no value table")
				}
				m.varpoints += vp
				if (vp.isEnum) vp.decision
				else if (Types.dataType(v as EObject) instanceof BooleanType) '''(«vp.decision» = 1)'''
				else '''«vp.x»[«vp.decision»]'''
			}
			Param: {
				val value = v.initializedTo
				if (value === null) unsupported(e, "param '" + v.name + "' has no default value") else translate(value, m)
			}
			default:
				unsupported(e, "rules may read contexts, properties, params with a default and varpoints; '" + v?.name + "' is none of them")
		}
	}

	def private metric(Property p) {
		properties += p
		Names.metric(p)
	}

	def private enumIndex(EnumValue e) {
		val literal = e.literal
		val type = literal?.eContainer
		if (type instanceof EnumType) String.valueOf(type.literals.indexOf(literal)) else unsupported(e, "the literal does not belong to an enumeration")
	}

	def private function(FunctionCall e, Mentions m) {
		val arity = switch e.function {
			case "abs", case "sqrt", case "exp": 1
			case "pow", case "min", case "max": 2
			default: -1
		}
		if (arity != e.args.size) {
			return unsupported(e, "rules may call abs, sqrt, exp (one argument), pow, min and max (two arguments)")
		}
		'''«e.function»(«FOR a : e.args SEPARATOR ', '»«translate(a, m)»«ENDFOR»)'''
	}

	/** The numeric (non-boolean) varpoint an expression reads directly, or null. */
	def private numericVarpoint(Expression e) {
		if (e instanceof VariableRef) {
			val v = e.variable
			if (v instanceof VariationPoint) {
				val vp = varpoints.get(v)
				if (vp !== null && !vp.isEnum && Types.dataType(v as EObject) instanceof NumericType) {
					return vp
				}
			}
		}
		null
	}

	def private unsupported(Expression e, String reason) {
		val node = NodeModelUtils.findActualNodeFor(e)
		val text = if(node === null) "" else NodeModelUtils.getTokenText(node)
		errors += new GenerationError(e, "cannot generate MiniZinc for '" + text + "': " + reason)
		"false"
	}

	/** The MiniZinc type of a context parameter (docs/io-json.md). */
	def static String mznType(Context c) {
		switch Types.dataType(c as EObject) {
			BooleanType, EventType: "bool"
			EnumType: "int"
			default: "float"
		}
	}
}
