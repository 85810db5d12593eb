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
import org.miron.dsl.miron.util.MironSwitch
import org.miron.dsl.roqme.util.RoqmeSwitch
import org.miron.dsl.roqme.Variable
import org.eclipse.emf.ecore.util.ComposedSwitch

/**
 * Translates the RoQME expressions of MIRoN rules to MiniZinc. Contexts and properties become
 * parameters (context_&lt;ns&gt;_&lt;c&gt;, metric_&lt;ns&gt;_&lt;p&gt;), varpoints their decision
 * (enum: the index &lt;vp&gt;_var, number: &lt;vp&gt;_x[&lt;vp&gt;_var]), enum literals their
 * 0-based index, and "=" on a numeric varpoint means "within half a step" so that a value between
 * two samples still selects the nearest one. What has no MiniZinc meaning (event patterns,
 * timers, windows over time) is reported as a GenerationError on the offending expression.
 *
 * A comparison that reads varpoints is tabulated over their value indexes: it becomes
 * {@code vp_var in {vp_i | vp_i in 0..vp_n-1 where <comparison on vp_x[vp_i]>}} (a mixed-radix
 * index for several varpoints), a set MiniZinc computes while flattening, from the parameters,
 * in the same double arithmetic as the native backend. No float variable is left: Gecode's float
 * bounds used to refuse exact values at the ends of a range (an inactive rule's
 * {@code v_x[v_var] - c/2} one ulp past its computed bound made v = 2.0 infeasible), and the float
 * element constraints were most of the flattening time. Only comparisons over more than
 * {@link #TABLE_LIMIT} value combinations keep float arithmetic on the decisions.
 * Partial functions go through miron_sqrt/miron_pow/miron_exp (MiniZincGenerator), which are
 * undefined, hence false in their Boolean context, where MiniZinc's own would abort the solve.
 */
class ExpressionToMiniZinc {
	/** What one expression reads: the rule guards use it. */
	static class Mentions {
		public val Set<Context> contexts = new LinkedHashSet
		public val Set<SampledVariationPoint> varpoints = new LinkedHashSet
	}

	/** Largest number of value combinations a comparison is tabulated over. */
	public static val TABLE_LIMIT = 250_000L

	val Map<VariationPoint, SampledVariationPoint> varpoints
	val List<GenerationError> errors
	/** Inside a tabulated comparison: varpoints read it are referred to by their index (vp_i). */
	var boolean tabulating
	/** Inside a comparison too large to tabulate: float arithmetic on the decisions. */
	var boolean floatVariables
	/** Every property and context any translated expression read, in order of first mention. */
	public val Set<Property> properties = new LinkedHashSet
	public val Set<Context> contexts = new LinkedHashSet

	new(Map<VariationPoint, SampledVariationPoint> varpoints, List<GenerationError> errors) {
		this.varpoints = varpoints
		this.errors = errors
	}

	/**
	 * Expressions by class, on the switch EMF generates from roqme.ecore: an expression class with
	 * no case here reaches defaultCase, which reports it at its position.
	 */
	val RoqmeSwitch<String> expressions = new RoqmeSwitch<String>() {
		override caseBinaryExpression(BinaryExpression e) { binary(e, mentions).toString }
		override caseUnaryExpression(UnaryExpression e) { unary(e, mentions).toString }
		override caseConditionalExpression(ConditionalExpression e) {
			val m = mentions
			'''(if «translate(e.condition, m)» then «translate(e.ifTrue, m)» else «translate(e.ifFalse, m)» endif)'''.toString
		}
		override caseVariableRef(VariableRef e) { reference(e) }
		override caseBeliefExpression(BeliefExpression e) {
			if (e.belief instanceof Property) metric(e.belief as Property) else unsupported(e, "only properties have a MiniZinc parameter (metric_...)")
		}
		override caseNumericValue(NumericValue e) { Numbers.mzn(e.value) }
		override caseBooleanValue(BooleanValue e) { String.valueOf(e.value) }
		override caseEventValue(EventValue e) { "true" }
		override caseEnumValue(EnumValue e) { enumIndex(e) }
		override caseFunctionCall(FunctionCall e) { function(e, mentions).toString }
		override defaultCase(EObject e) { unsupported(e as Expression, UNSUPPORTED_EXPRESSION) }
	}

	/**
	 * The variable a reference reads, by class: RoQME's (properties, contexts, params) and MIRoN's
	 * varpoints, on the two generated switches; any other variable reaches defaultCase.
	 */
	val ComposedSwitch<String> variables = new ComposedSwitch<String>(#[
		new RoqmeSwitch<String>() {
			override caseProperty(Property p) { metric(p) }
			override caseContext(Context c) { context(c) }
			override caseParam(Param p) { param(p) }
			override defaultCase(EObject v) { unknownVariable(v) }
		},
		new MironSwitch<String>() {
			override caseVariationPoint(VariationPoint v) { varpoint(v) }
			override defaultCase(EObject v) { unknownVariable(v) }
		}
	])

	/** What the expression being translated reads (the Mentions of translate). */
	var Mentions mentions
	/** The reference being translated: where a variable it cannot read is reported. */
	var VariableRef referenceInTranslation

	static val UNSUPPORTED_EXPRESSION = "rules may use numbers, booleans, enum literals, contexts, properties, varpoints, arithmetic, comparisons, and/or/not, ?: and abs/sqrt/exp/pow/min/max"

	def String translate(Expression e, Mentions m) {
		if (e === null) {
			return unsupported(null, UNSUPPORTED_EXPRESSION)
		}
		val outer = mentions
		mentions = m
		try {
			expressions.doSwitch(e)
		} finally {
			mentions = outer
		}
	}

	def private binary(BinaryExpression e, Mentions m) {
		val op = e.operator
		if (!tabulating && !floatVariables && COMPARISONS.contains(op)) {
			return tabulated(e, m)
		}
		if (op == BinaryOperator.EQ || op == BinaryOperator.NE) {
			val vp = numericVarpoint(e.left) ?: numericVarpoint(e.right)
			if (vp !== null) {
				// Within half a step of the wanted value: the nearest sample is selected.
				val other = if (numericVarpoint(e.left) !== null) e.right else e.left
				m.varpoints += vp
				val distance = '''abs(«value(vp)» - «translate(other, m)»)'''
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

	def private String reference(VariableRef e) {
		if (e.variable === null) {
			return unsupported(e, "rules may read contexts, properties, params with a default and varpoints; 'null' is none of them")
		}
		val outer = referenceInTranslation
		referenceInTranslation = e
		try {
			variables.doSwitch(e.variable)
		} finally {
			referenceInTranslation = outer
		}
	}

	def private String context(Context v) {
		val type = Types.dataType(v as EObject)
		if (type instanceof TimeType || type === null) {
			return unsupported(referenceInTranslation, "context '" + v.name + "' has a type without MiniZinc parameter (time)")
		}
		contexts += v
		mentions.contexts += v
		Names.context(v)
	}

	def private String varpoint(VariationPoint v) {
		val vp = varpoints.get(v)
		if (vp === null) {
			return unsupported(referenceInTranslation, "varpoint '" + v.name + "' has no value table")
		}
		mentions.varpoints += vp
		if (vp.isEnum) index(vp)
		else if (Types.dataType(v as EObject) instanceof BooleanType) '''(«index(vp)» = 1)'''.toString
		else value(vp)
	}

	def private String param(Param v) {
		val value = v.initializedTo
		if (value === null) unsupported(referenceInTranslation, "param '" + v.name + "' has no default value") else translate(value, mentions)
	}

	def private String unknownVariable(EObject v) {
		val name = if (v instanceof Variable) v.name
		unsupported(referenceInTranslation, "rules may read contexts, properties, params with a default and varpoints; '" + name + "' is none of them")
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
		// MiniZinc's own sqrt/pow/exp abort a solve on a parameter outside their domain.
		val name = if (!floatVariables && PARTIAL.contains(e.function)) "miron_" + e.function else e.function
		'''«name»(«FOR a : e.args SEPARATOR ', '»«translate(a, m)»«ENDFOR»)'''
	}

	static val PARTIAL = #{"sqrt", "pow", "exp"}
	static val COMPARISONS = #{BinaryOperator.EQ, BinaryOperator.NE, BinaryOperator.LT, BinaryOperator.GT,
		BinaryOperator.LE, BinaryOperator.GE}

	/**
	 * A comparison as a set of value indexes (see the class comment); unchanged when it reads no
	 * varpoint (then it is a parameter expression already).
	 */
	def private String tabulated(BinaryExpression e, Mentions m) {
		val read = varpointsIn(e)
		var combinations = 1L
		for (vp : read) {
			combinations = Math.min(Long.MAX_VALUE / 2, combinations * Math.max(1, vp.size))
		}
		if (combinations > TABLE_LIMIT) {
			floatVariables = true
			try {
				return binary(e, m).toString
			} finally {
				floatVariables = false
			}
		}
		tabulating = true
		val body = try {
			binary(e, m).toString
		} finally {
			tabulating = false
		}
		if (read.empty) {
			return body
		}
		var decision = read.head.decision
		var index = read.head.name + "_i"
		for (vp : read.tail) {
			decision = '''(«decision» * «vp.n» + «vp.decision»)'''
			index = '''(«index» * «vp.n» + «vp.name»_i)'''
		}
		val generators = read.map['''«name»_i in 0..«n»-1'''].join(", ")
		'''(«decision» in {«index» | «generators» where «body»})'''
	}

	/** The varpoints an expression reads (through parameters' default values too), in order of mention. */
	def private Set<SampledVariationPoint> varpointsIn(EObject e) {
		val found = new LinkedHashSet<SampledVariationPoint>
		collect(e, found)
		found
	}

	def private void collect(EObject o, Set<SampledVariationPoint> found) {
		if (o instanceof VariableRef) {
			val v = o.variable
			if (v instanceof VariationPoint) {
				val vp = varpoints.get(v)
				if (vp !== null) {
					found += vp
				}
			} else if (v instanceof Param && (v as Param).initializedTo !== null) {
				collect((v as Param).initializedTo, found)
			}
		}
		o.eContents.forEach[collect(it, found)]
	}

	/** The decision, or the comprehension's index while tabulating. */
	def private index(SampledVariationPoint vp) {
		if (tabulating) vp.name + "_i" else vp.decision
	}

	/** The value of a numeric varpoint. */
	def private value(SampledVariationPoint vp) {
		'''«vp.x»[«index(vp)»]'''.toString
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
